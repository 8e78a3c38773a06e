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

}  // namespace
}  // namespace springcheck
