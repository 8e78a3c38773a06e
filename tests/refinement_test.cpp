// The grid convergence estimate (compare/studies/refinement.h) on sequences of known order.
// ctest-label: unit
#include "compare/studies/refinement.h"

#include <gtest/gtest.h>

#include <cmath>

namespace springcheck {
namespace {

// q = q0 + C h^p exactly: the estimate returns p and q0 to round-off, for doubling and for
// uneven resolutions.
TEST(Refinement, AnExactPowerLawGivesItsOrderAndLimit) {
  for (double p : {1.0, 2.0, 3.5}) {
    for (const std::vector<int>& n : {std::vector<int>{8, 16, 32}, std::vector<int>{10, 24, 50, 90}}) {
      std::vector<double> q;
      for (int r : n) q.push_back(0.75 - 4.0 * std::pow(1.0 / r, p));
      const RefinementEstimate e = estimateRefinement(n, q);
      ASSERT_TRUE(e.order) << e.reason;
      EXPECT_NEAR(*e.order, p, 1e-9);
      EXPECT_NEAR(*e.limit, 0.75, 1e-12);
    }
  }
}

// Differences that grow, or change sign, have no order: the estimate says why instead of
// inventing one.
TEST(Refinement, DivergingOrOscillatingValuesHaveNoOrder) {
  EXPECT_FALSE(estimateRefinement({8, 16, 32}, {0.181, 0.145, 0.043}).order);  // growing steps
  EXPECT_FALSE(estimateRefinement({8, 16, 32}, {1.0, 1.1, 1.05}).order);       // sign change
  EXPECT_FALSE(estimateRefinement({8, 16}, {1.0, 1.1}).order);                 // too few
}

std::vector<double> powerLaw(const std::vector<int>& n, double p) {
  std::vector<double> q;
  for (int r : n) q.push_back(0.75 - 4.0 * std::pow(1.0 / r, p));
  return q;
}

// Three points fit some order and some limit whatever they are: the verdict quotes one only
// when theory's expected order agrees (within 30 %), or a fourth resolution's second triple does.
TEST(RefinementVerdict, ALimitNeedsTheExpectedOrderOrASecondTripleThatAgrees) {
  const std::vector<int> three{4, 8, 16}, four{4, 8, 16, 32};
  EXPECT_TRUE(refinementVerdict(three, powerLaw(three, 2.1), 2.0).converged);
  const RefinementVerdict slow = refinementVerdict(three, powerLaw(three, 1.31), 2.0);
  EXPECT_FALSE(slow.converged);
  EXPECT_NE(slow.text.find("not converged at these resolutions"), std::string::npos) << slow.text;
  EXPECT_NE(slow.text.find("expected 2"), std::string::npos) << slow.text;
  const RefinementVerdict unheld = refinementVerdict(three, powerLaw(three, 0.88), std::nullopt);
  EXPECT_FALSE(unheld.converged);
  EXPECT_NE(unheld.text.find("no expected order"), std::string::npos) << unheld.text;
  EXPECT_TRUE(refinementVerdict(four, powerLaw(four, 0.88), std::nullopt).converged);
  // Pre-asymptotic: the coarse triple at order 0.4, the fine one at 2 (no expected order).
  std::vector<double> bent = powerLaw(three, 0.4);
  bent.push_back(bent.back() - (bent[1] - bent[2]) / 4.0);
  EXPECT_FALSE(refinementVerdict(four, bent, std::nullopt).converged);
  EXPECT_FALSE(refinementVerdict(three, {0.181, 0.145, 0.043}, 2.0).converged);  // no order at all
}

}  // namespace
}  // namespace springcheck
