// recommend: the cheapest choice under an error bound, and the runner-up, worked out by hand.
// ctest-label: unit
#include "compare/studies/recommend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "compare/studies/sweep.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;

SweepRow row(const std::string& engine, const std::string& integrator, double dt,
             const std::string& status, const std::string& error, double wall, long evaluations) {
  SweepRow r;
  r.c = {0, "s.json", engine, integrator, dt, 1.0, 0.0};
  r.status = status;
  if (!error.empty()) r.error = std::stod(error);
  r.wall_seconds = wall;
  r.derivative_evaluations = evaluations;
  r.linear_iterations = 0;
  return r;
}

TEST(Recommend, PicksTheCheapestRowUnderTheBoundAndTheNextAsRunnerUp) {
  const std::vector<SweepRow> rows = {
      row("mysim", "euler", 0.01, "ok", "0.5", 0.001, 100),          // cheapest, error too large
      row("mysim", "rk4", 0.01, "ok", "1e-4", 0.004, 400),           // meets: 4 ms
      row("mysim", "rk4", 0.005, "ok", "6e-6", 0.008, 800),          // meets: 8 ms
      row("bullet-deformable", "-", 0.01, "blowup", "", 0.0005, 0),  // blew up: never chosen
      row("mysim", "verlet", 0.01, "ok", "2e-4", 0.002, 200),        // just over the bound
  };
  const auto found = recommend(rows, 1.5e-4, Cost::WallTime);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_TRUE(found[0].best && found[0].runner_up);
  EXPECT_EQ(found[0].best->integrator, "rk4");
  EXPECT_EQ(found[0].best->dt, 0.01);
  EXPECT_EQ(found[0].runner_up->dt, 0.005);
  EXPECT_EQ(found[0].candidates, 4);  // the blown-up row has no error to judge
  EXPECT_EQ(found[0].meeting, 2);
  // A looser bound lets Verlet in, which is cheaper than both RK4 rows.
  EXPECT_EQ(recommend(rows, 3e-4, Cost::WallTime)[0].best->integrator, "verlet");
  // Nothing meets a bound below every error.
  EXPECT_FALSE(recommend(rows, 1e-9, Cost::WallTime)[0].best);
}

TEST(Recommend, EachEngineGetsItsOwnCheapestChoiceUnderTheBoundCheapestFirst) {
  const std::vector<SweepRow> rows = {
      row("bullet-deformable", "-", 0.01, "ok", "2e-3", 0.001, 0),   // too inaccurate
      row("bullet-deformable", "-", 0.005, "ok", "5e-4", 0.006, 0),  // deformable's best
      row("bullet-deformable", "-", 0.0025, "ok", "2e-4", 0.012, 0),
      row("mysim", "rk4", 0.01, "ok", "1e-4", 0.004, 400),  // mysim's best (any integrator)
      row("mysim", "verlet", 0.01, "ok", "3e-4", 0.005, 200),
      row("bullet-implicit", "-", 0.01, "ok", "9e-3", 0.002, 0),  // never meets it
  };
  const auto found = recommend(rows, 1e-3, Cost::WallTime);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_EQ(found[0].per_engine.size(), 2u);
  EXPECT_EQ(found[0].per_engine[0].engine, "mysim");
  EXPECT_EQ(found[0].per_engine[0].integrator, "rk4");
  EXPECT_EQ(found[0].per_engine[1].engine, "bullet-deformable");
  EXPECT_EQ(found[0].per_engine[1].dt, 0.005);
}

// The circle x' = -y, y' = x over 3 s: forward Euler's radius grows as (1 + h^2)^(n/2), by 7.8 %
// at h = 0.05 (60 steps); RK4's phase error is about t h^4 / 120 = 2.5e-6 at h = 0.1. Under
// 1e-4 only RK4 qualifies, and by work (4 evaluations a step) h = 0.1 (120 evaluations) beats
// h = 0.05 (240). Under 1e-9 nothing does (RK4 at h = 0.05: 1.6e-7).
TEST(Recommend, OnTheCircleTheAnswerIsTheOneWorkedOutByHand) {
  EngineRegistry registry;
  auto spec = parseSweepSpec(
      R"({"name": "circle", "scenes": [")" SPRINGCHECK_SOURCE_DIR
      R"(/scenes/seed/circle.json"], "integrators": ["euler", "rk4"], "dt": [0.1, 0.05],
          "duration": 3.0, "reference": "closed_form"})",
      SPRINGCHECK_SOURCE_DIR "/compare/sweeps/circle.json", registry);
  ASSERT_TRUE(spec) << spec.error();
  const fs::path out =
      fs::temp_directory_path() / ("springcheck_recommend_" + std::to_string(::getpid()) + ".csv");
  ASSERT_TRUE(runSweep(registry, *spec, out.string(), {.jobs = 1, .resume = false}));
  const auto rows = readSweepTable(out.string());
  fs::remove(out);
  ASSERT_TRUE(rows);
  const auto found = recommend(*rows, 1e-4, Cost::Work);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_TRUE(found[0].best && found[0].runner_up);
  EXPECT_EQ(found[0].best->integrator, "rk4");
  EXPECT_DOUBLE_EQ(found[0].best->dt, 0.1);
  EXPECT_EQ(found[0].best->work, 120);
  EXPECT_EQ(found[0].runner_up->integrator, "rk4");
  EXPECT_DOUBLE_EQ(found[0].runner_up->dt, 0.05);
  EXPECT_EQ(found[0].meeting, 2);
  EXPECT_FALSE(recommend(*rows, 1e-9, Cost::Work)[0].best);
}

}  // namespace
}  // namespace springcheck
