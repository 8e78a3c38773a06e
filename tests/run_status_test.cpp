// What a run's status says when it cannot do what was asked, and the trajectory distance of runs
// that sampled different times.
// ctest-label: unit
// ctest-label RunStatus: physics
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "compare/metrics/run_metrics.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {


mysim::Scene chainScene(const std::string& integrator_fields) {
  auto scene = mysim::parseScene(
      R"({"system": {"type": "chain", "particles": 4, "rest_length": 0.1, "particle_mass": 0.01,
          "stiffness": 100}, "forces": {"gravity": [0, -9.8, 0]},
          "integrator": {"dt": 0.01, "duration": 0.2, )" +
          integrator_fields + "}}",
      "status.json");
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

// dopri5 asked for 1e-30 (tighter than double precision) once ran forever; it must stop at its
// step limits and say so.
TEST(RunStatus, AnUnreachableAdaptiveToleranceStopsTheRunAsAStepLimit) {
  const auto run = EngineRegistry().run(
      "mysim", chainScene(R"("name": "dopri5", "abs_tolerance": 1e-30, "rel_tolerance": 1e-30)"));
  ASSERT_TRUE(run) << run.error().message;
  EXPECT_EQ(run->status(), "step-limit");
  ASSERT_TRUE(run->blowup);
  EXPECT_LT(run->blowup->time, 0.2);
}

// A CG that cannot converge in one iteration finishes the run but says the run is less accurate
// than asked, instead of only counting it.
TEST(RunStatus, LinearSolvesThatStopShortAreAStatusNotJustACount) {
  const auto run = EngineRegistry().run(
      "mysim",
      chainScene(R"("name": "backward-euler", "cg_max_iterations": 1, "cg_tolerance": 1e-12)"));
  ASSERT_TRUE(run) << run.error().message;
  EXPECT_FALSE(run->blowup);
  EXPECT_GT(run->counts.solver_failures, 0);
  EXPECT_EQ(run->status(), "solver-not-converged");
  const auto fine = EngineRegistry().run("mysim", chainScene(R"("name": "backward-euler")"));
  EXPECT_EQ(fine->status(), "ok");
}

// Runs whose durations are not whole multiples of their steps end at different times, each with
// a last frame of its own: the distance is taken over the times both sampled.
TEST(TrajectoryDistance, IsTakenOverTheTimesBothRunsSampled) {
  auto record = [](std::vector<double> times, double offset) {
    mysim::RunRecord r;
    r.times = times;
    for (double t : times) {
      mysim::ParticleRows f = mysim::ParticleRows::Zero(2, 6);
      f(0, 0) = t + offset;
      f(1, 0) = t + offset;
      r.frames.push_back(f);
    }
    return r;
  };
  const mysim::RunRecord a = record({0.0, 0.16, 0.32, 0.34}, 0.0);
  const mysim::RunRecord b = record({0.0, 0.16, 0.32, 0.3412}, 0.01);
  const auto d = trajectoryDistance(a, b);
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->max_rms, 0.01, 1e-15);   // every shared frame is 0.01 apart
  EXPECT_NEAR(d->last_rms, 0.01, 1e-15);  // the last shared time, 0.32
  EXPECT_FALSE(trajectoryDistance(record({0.05}, 0.0), record({0.07}, 0.0)));
}

}  // namespace
}  // namespace springcheck
