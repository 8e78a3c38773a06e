// The seed's simple system x' = -y, y' = x: each explicit integrator multiplies the radius by
// |R(ih)| per step, where R is its stability polynomial. Exact figures, so tight tolerances.
// ctest-label: physics
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

TEST(Circle, IsNotAParticleSystemAndEveryIntegratorThatTakesItKeepsItOnTheCircle) {
  CircleSystem circle({1.0, 0.0});
  EXPECT_EQ(circle.particles(), nullptr);
  // Those the catalogue says take first-order systems step the circle's ODE itself: 0.1 s at
  // h = 0.01 leaves every method of order >= 1 within h * t of the unit circle.
  for (const IntegratorInfo& info : integratorCatalog()) {
    if (info.needs_particles) continue;
    auto method = testing::integratorNamed(info.name);
    const State s = testing::integrate(circle, *method, circle.initialState(), 0.01, 10);
    EXPECT_NEAR(s.y.head<2>().norm(), 1.0, 1e-3) << info.name;
  }
}

// The circle's mechanical twin traces the same radius, step by step, as the first-order form:
// each coordinate of x'' = -x is an oscillator whose phase point turns like the circle's.
TEST(Circle, MechanicalTwinRadiusEqualsTheFirstOrderRadiusUnderEveryExplicitMethod) {
  Model circle;
  circle.circle_start = Eigen::Vector2d(0.6, 0.8);
  ParticleSystem twin(circleTwin(circle), BlowUpLimits{});
  CircleSystem first_order(*circle.circle_start);
  for (const char* name : {"euler", "trapezoidal", "rk4"}) {
    State a = first_order.initialState(), b = twin.initialState();
    auto ma = testing::integratorNamed(name), mb = testing::integratorNamed(name);
    for (int n = 0; n < 100; ++n) {
      ma->step(first_order, a, 0.1);
      mb->step(twin, b, 0.1);
    }
    const Eigen::Vector2d twin_xy = at3(b.y, kCircleTwinParticle).head<2>();
    EXPECT_NEAR(twin_xy.norm(), a.y.norm(), 1e-12) << name;
    EXPECT_NEAR((twin_xy - a.y).norm(), 0.0, 1e-12) << name;
  }
}

}  // namespace
}  // namespace mysim
