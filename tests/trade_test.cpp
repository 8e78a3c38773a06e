// The trade's physical reference and its choice (compare/studies/physical_reference.h, trade.h)
// on constructed sequences and tables: what is recommended, what never is, and why.
// ctest-label: unit
#include "compare/studies/trade.h"

#include <gtest/gtest.h>

#include <cmath>

namespace springcheck {
namespace {

// q = 0.5 + 3 h^2 at 4, 8, 16, 32 cells: the limit is 0.5 to round-off, order 2 from both
// triples, nothing to warn of, and the uncertainty Roache's 1.25 |q_32 - limit|.
TEST(PhysicalReference, ASecondOrderSequenceGivesItsLimitAndTrustsIt) {
  const std::vector<int> n{4, 8, 16, 32};
  std::vector<double> q;
  for (int r : n) q.push_back(0.5 + 3.0 / (r * r));
  const PhysicalReference ref = refinementReference("tip_drop", n, q, "test");
  ASSERT_TRUE(ref.value) << ref.reason;
  EXPECT_NEAR(*ref.value, 0.5, 1e-12);
  EXPECT_NEAR(*ref.order, 2.0, 1e-9);
  EXPECT_NEAR(*ref.coarser_order, 2.0, 1e-9);
  EXPECT_TRUE(ref.warning.empty()) << ref.warning;
  EXPECT_NEAR(ref.uncertainty, 1.25 * 3.0 / (32 * 32), 1e-12);
}

// A sequence whose coarse triple converges at order 0.3 and whose fine one at order 1.9 (not in
// the asymptotic range yet): a limit, but said not to be trusted, with both orders.
TEST(PhysicalReference, OrdersThatDisagreeAreSaidNotToBeTrusted) {
  const std::vector<int> n{4, 8, 16, 32};
  // Differences d1, d2 = d1 / 2^0.3, d3 = d2 / 2^1.9.
  const double d1 = 0.1, d2 = d1 / std::pow(2.0, 0.3), d3 = d2 / std::pow(2.0, 1.9);
  const std::vector<double> q{1.0, 1.0 - d1, 1.0 - d1 - d2, 1.0 - d1 - d2 - d3};
  const PhysicalReference ref = refinementReference("drape_coefficient", n, q, "test");
  ASSERT_TRUE(ref.value);
  EXPECT_NE(ref.warning.find("orders disagree: 0.3 then 1.9"), std::string::npos) << ref.warning;
}

// Differences that change sign: no limit, and the reason says so (a result, not a number).
TEST(PhysicalReference, ANonMonotoneSequenceHasNoLimit) {
  const PhysicalReference ref =
      refinementReference("drape_folds", {4, 8, 16}, {6.0, 8.0, 7.0}, "test");
  EXPECT_FALSE(ref.value);
  EXPECT_NE(ref.reason.find("no limit"), std::string::npos) << ref.reason;
}

SweepRow row(int resolution, const std::string& integrator, double dt, double value, double wall,
             const std::string& status = "ok", double drift = 0.0) {
  SweepRow r;
  r.c.scene = "grid/strip_r" + std::to_string(resolution) + ".json";
  r.c.engine = "mysim";
  r.c.integrator = integrator;
  r.c.dt = dt;
  r.status = status;
  r.wall_seconds = wall;
  if (status == "blowup") r.blowup_time = 0.1;
  if (status == "ok") r.quantities["tip_drop"] = {value, value - drift};
  return r;
}

TradeInputs inputs(std::vector<SweepRow> rows) {
  TradeInputs in;
  in.rows = std::move(rows);
  for (int n : {4, 8, 16}) in.resolution_of_scene["grid/strip_r" + std::to_string(n) + ".json"] = n;
  PhysicalReference exact;
  exact.quantity = "tip_drop";
  exact.value = 1.0;
  exact.closed_form = true;
  in.closed_form = exact;
  return in;
}

// The cheapest row blew up, the next still moved by more than a tenth of the bound over the
// run's last tenth: neither is recommended, and each says why; the third, within the bound, is.
TEST(Trade, ABlownUpOrUnsettledSetupIsNeverRecommended) {
  const TradeInputs in = inputs({row(4, "xpbd", 0.01, 0.0, 0.001, "blowup"),
                                 row(8, "xpbd", 0.01, 1.001, 0.002, "ok", 0.002),
                                 row(16, "xpbd", 0.01, 1.003, 0.004),
                                 row(16, "backward-euler", 0.01, 1.001, 0.01)});
  const TradeAnswer a = analyseTrade(in, {"tip_drop", 0.01, true, Cost::WallTime});
  ASSERT_TRUE(a.recommended);
  EXPECT_EQ(a.setups[*a.recommended].resolution, 16);
  EXPECT_EQ(a.setups[*a.recommended].integrator, "xpbd");
  EXPECT_EQ(a.setups[*a.runner_up].integrator, "backward-euler");
  EXPECT_NE(a.setups[0].excluded.find("blew up at t = 0.1 s"), std::string::npos);
  EXPECT_NE(a.setups[1].excluded.find("did not settle"), std::string::npos);
  EXPECT_EQ(a.blew_up, 1);
  EXPECT_EQ(a.unsettled, 1);
  EXPECT_NEAR(a.bound, 0.01, 1e-15);
}

// No row within the bound: nothing recommended, the closest named.
TEST(Trade, NoSetupWithinTheBoundLeavesTheClosestNamed) {
  const TradeInputs in = inputs({row(4, "xpbd", 0.01, 1.2, 0.001), row(8, "xpbd", 0.01, 0.95, 0.002)});
  const TradeAnswer a = analyseTrade(in, {"tip_drop", 0.01, false, Cost::WallTime});
  EXPECT_FALSE(a.recommended);
  ASSERT_TRUE(a.closest);
  EXPECT_EQ(a.setups[*a.closest].resolution, 8);
}

// The Pareto front of a family keeps only setups more accurate than every cheaper one.
TEST(Trade, TheParetoFrontKeepsOnlySetupsMoreAccurateThanEveryCheaperOne) {
  const TradeInputs in = inputs({row(4, "xpbd", 0.01, 1.1, 0.001), row(8, "xpbd", 0.01, 1.2, 0.002),
                                 row(16, "xpbd", 0.01, 1.01, 0.004)});
  const TradeAnswer a = analyseTrade(in, {"tip_drop", 0.5, false, Cost::WallTime});
  const std::vector<std::size_t> front = a.pareto.at("position-based");
  ASSERT_EQ(front.size(), 2u);
  EXPECT_EQ(a.setups[front[0]].resolution, 4);
  EXPECT_EQ(a.setups[front[1]].resolution, 16);
}

}  // namespace
}  // namespace springcheck
