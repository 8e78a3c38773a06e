// The seed's simple system x' = -y, y' = x: each explicit integrator multiplies the radius by
// |R(ih)| per step, where R is its stability polynomial. Exact figures, so tight tolerances.
#include <gtest/gtest.h>

#include "mysim/circle_system.h"
#include "test_support.h"

namespace mysim {
namespace {

double radiusAfter(const std::string& integrator, double h, int steps) {
  CircleSystem circle({1.0, 0.0});
  auto method = testing::integratorNamed(integrator);
  return testing::integrate(circle, *method, circle.initialState(), h, steps).y.norm();
}

TEST(Circle, ForwardEulerRadiusGrowsBySqrtOnePlusHSquaredPerStep) {
  for (double h : {0.01, 0.04, 0.1}) {
    const int n = 100;
    // Relative round-off over 100 steps stays near 1e-14.
    EXPECT_NEAR(radiusAfter("euler", h, n), std::pow(std::sqrt(1 + h * h), n), 1e-12) << h;
  }
}

TEST(Circle, TrapezoidalRadiusGrowsBySqrtOnePlusHFourthOverFour) {
  for (double h : {0.01, 0.04, 0.1}) {
    const int n = 100;
    EXPECT_NEAR(radiusAfter("trapezoidal", h, n), std::pow(std::sqrt(1 + std::pow(h, 4) / 4), n),
                1e-12)
        << h;
  }
}

TEST(Circle, Rk4RadiusShrinksBySqrtOneMinusH6Over72PlusH8Over576) {
  for (double h : {0.04, 0.1, 0.5}) {
    const int n = 100;
    const double per_step = std::sqrt(1 - std::pow(h, 6) / 72 + std::pow(h, 8) / 576);
    EXPECT_NEAR(radiusAfter("rk4", h, n), std::pow(per_step, n), 1e-12) << h;
  }
}

TEST(Circle, SeedObservationEulerSpiralsOutTrapezoidalHoldsRk4Best) {
  const double h = 0.04;
  const int n = 785;  // about 5 turns
  const double euler = std::abs(radiusAfter("euler", h, n) - 1);
  const double trapezoidal = std::abs(radiusAfter("trapezoidal", h, n) - 1);
  const double rk4 = std::abs(radiusAfter("rk4", h, n) - 1);
  EXPECT_GT(euler, 0.5);  // (1 + 0.0016)^(785/2) - 1 = 0.87
  EXPECT_LT(trapezoidal, 1e-3);
  EXPECT_LT(rk4, trapezoidal);
}

TEST(Circle, SecondOrderIntegratorsAreRefusedForAFirstOrderSystem) {
  CircleSystem circle({1.0, 0.0});
  EXPECT_EQ(circle.particles(), nullptr);
  for (const IntegratorInfo& info : integratorCatalog()) {
    EXPECT_EQ(testing::integratorNamed(info.name)->needsParticles(), info.needs_particles);
  }
}

}  // namespace
}  // namespace mysim
