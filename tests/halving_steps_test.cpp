// A step an iterative solver cannot solve is redone as two halves (integrators/halving_steps.h):
// the pieces tile the step exactly, the level that worked is kept and a coarser one retried after
// eight calm steps, a scene no level solves stops halving, a run whose steps all solve is the
// plain solver's bits, and VBD solves the shipped cantilever where its plain passes stop short.
// ctest-label: physics
// 4.6 s in Release, ten times that under the sanitizers, where the three tests above run the
// halving's code:
// ctest-label HalvingOnTheCantilever: physics,releaseonly
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "integrators/halving_steps.h"
#include "mysim/circle_system.h"
#include "mysim/scene_file.h"
#include "mysim/state_hash.h"
#include "test_support.h"

namespace mysim {
namespace {

// A solver that solves pieces no longer than `longest` and stops at its cap (a solver failure)
// on longer ones; it advances y[0] by the piece and records every piece it was given.
class SolvesUpTo final : public Integrator {
 public:
  SolvesUpTo(double longest, std::vector<double>& pieces) : longest_(longest), pieces_(pieces) {}
  StepCounts step(OdeSystem&, State& s, double h) override {
    pieces_.push_back(h);
    s.y[0] += h;
    s.t += h;
    return {.accepted = 1, .linear_iterations = 1, .solver_failures = h > longest_ ? 1 : 0};
  }

 private:
  double longest_;
  std::vector<double>& pieces_;
};

struct Halving {
  std::vector<double> pieces;
  CircleSystem system{Eigen::Vector2d(1.0, 0.0)};
  State s{.t = 0.0, .y = Eigen::Vector2d(0.0, 0.0)};
};

TEST(HalvingSteps, AnUnsolvedStepIsRedoneInHalvesUntilItsPiecesSolveAndTheyTileTheStep) {
  Halving run;
  const double h = 0.1;
  auto stepper = halvingUnsolvedSteps(std::make_unique<SolvesUpTo>(h / 5, run.pieces), 6);
  const StepCounts first = stepper->step(run.system, run.s, h);
  // h, two halves, four quarters fail; eight eighths solve.
  EXPECT_EQ(first.rejected, 7);
  EXPECT_EQ(first.accepted, 8);
  EXPECT_EQ(first.solver_failures, 0);
  EXPECT_EQ(first.linear_iterations, 15) << "a rejected try's passes were still done";
  EXPECT_DOUBLE_EQ(run.s.y[0], h) << "the accepted pieces cover the step once";
  EXPECT_EQ(run.s.t, h);
  // The next step starts at eighths: nothing rejected.
  run.pieces.clear();
  const StepCounts second = stepper->step(run.system, run.s, h);
  EXPECT_EQ(second.rejected, 0);
  EXPECT_EQ(run.pieces, std::vector<double>(8, h / 8));
}

TEST(HalvingSteps, AfterEightCalmStepsACoarserLevelIsTriedOnce) {
  Halving run;
  const double h = 0.1;
  auto stepper = halvingUnsolvedSteps(std::make_unique<SolvesUpTo>(h / 5, run.pieces), 6);
  long rejected = 0;
  for (int k = 0; k < 9; ++k) rejected += stepper->step(run.system, run.s, h).rejected;
  EXPECT_EQ(rejected, 7) << "the first step's tries only";
  // The tenth step tries quarters: its first quarter fails and the rest go at eighths.
  const StepCounts tenth = stepper->step(run.system, run.s, h);
  EXPECT_EQ(tenth.rejected, 1);
  EXPECT_EQ(tenth.accepted, 8);
  EXPECT_NEAR(run.s.y[0], 10 * h, 1e-12) << "eighty pieces' sum";
}

TEST(HalvingSteps, AtTheDeepestLevelAnUnsolvedPieceIsKeptAndHalvingStopsForTheRun) {
  Halving run;
  auto stepper = halvingUnsolvedSteps(std::make_unique<SolvesUpTo>(0.001, run.pieces), 2);
  const StepCounts counts = stepper->step(run.system, run.s, 0.1);
  // h and its first half fail; the first quarter (the deepest level) fails too and is kept; the
  // rest of the step goes on unhalved: the second quarter, then the second half whole.
  EXPECT_EQ(run.pieces, std::vector<double>({0.1, 0.05, 0.025, 0.025, 0.05}));
  EXPECT_EQ(counts.rejected, 2);
  EXPECT_EQ(counts.accepted, 3);
  EXPECT_EQ(counts.solver_failures, 3);
  EXPECT_DOUBLE_EQ(run.s.y[0], 0.1);
  EXPECT_EQ(run.s.t, 0.1);
  run.pieces.clear();
  const StepCounts next = stepper->step(run.system, run.s, 0.1);
  EXPECT_EQ(run.pieces, std::vector<double>({0.1})) << "whole steps, as the plain solver";
  EXPECT_EQ(next.rejected, 0);
  EXPECT_EQ(next.solver_failures, 1);
}

// The shipped cantilever at 16 cells and 1/60 s for its first 0.3 s (its stiff fall): plain VBD
// stops at its 1000-pass cap on some steps (measured: 12 of 18), halving solves every step; a run
// whose steps all solve at their step (the same strip at 2 ms, its own) is the same bits with and
// without halving.
Scene cantilever(double dt, bool halving) {
  std::ifstream file(std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/material/cantilever_strip.json");
  nlohmann::json j = nlohmann::json::parse(file);
  j["system"]["resolution"] = 16;
  j["integrator"] = {{"name", "vbd"}, {"dt", dt}, {"duration", 0.3}};
  if (!halving) j["integrator"]["max_halvings"] = 0;
  auto scene = parseScene(j.dump(), "cantilever_strip.json");
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

TEST(HalvingOnTheCantilever, VbdSolvesTheSixteenCellStripAtOneSixtiethWherePlainPassesStopAtTheCap) {
  const RunRecord plain = testing::simulateScene(cantilever(1.0 / 60.0, false));
  const RunRecord halved = testing::simulateScene(cantilever(1.0 / 60.0, true));
  EXPECT_GT(plain.counts.solver_failures, 0);
  EXPECT_FALSE(halved.blowup);
  EXPECT_EQ(halved.counts.solver_failures, 0);
  EXPECT_GT(halved.counts.rejected, 0);
  const RunRecord at_own = testing::simulateScene(cantilever(0.002, true));
  const RunRecord at_own_plain = testing::simulateScene(cantilever(0.002, false));
  EXPECT_EQ(at_own.counts.rejected, 0);
  EXPECT_EQ(hashRows(at_own.frames.back()), hashRows(at_own_plain.frames.back()));
}

}  // namespace
}  // namespace mysim
