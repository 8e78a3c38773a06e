// Global convergence orders on a damped oscillator against its exact solution, and the
// long-run behaviour theory predicts for each method.
// ctest-label: physics
#include <gtest/gtest.h>

#include "test_support.h"

namespace mysim {
namespace {

using testing::Oscillator;

// Phase-space error |(u, u'/w0) - exact| at time T.
double errorAt(const Oscillator& osc, const std::string& integrator, double h, double T) {
  ParticleSystem system(osc.model(), {});
  auto method = testing::integratorNamed(integrator);
  const long steps = std::lround(T / h);
  const State end = testing::integrate(system, *method, system.initialState(), h, steps);
  const double u = end.y[3] - osc.rest_length, v = end.y[9];
  return std::hypot(u - osc.displacement(T), (v - osc.velocity(T)) / osc.omega0());
}

struct OrderCase {
  std::string integrator;
  double expected_order;
  double h;  // coarsest step: in the asymptotic range, error far above round-off at h / 4
};

void PrintTo(const OrderCase& c, std::ostream* os) { *os << c.integrator; }

class ConvergenceOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(ConvergenceOrder, MatchesTheoryOnADampedOscillator) {
  const OrderCase& c = GetParam();
  Oscillator osc;
  osc.drag = 0.4;  // damping ratio 0.1: the velocity-dependent force must not spoil the order
  const double T = 2.0;
  const double e1 = errorAt(osc, c.integrator, c.h, T);
  const double e2 = errorAt(osc, c.integrator, c.h / 2, T);
  const double e3 = errorAt(osc, c.integrator, c.h / 4, T);
  const double order = std::log2(e2 / e3);
  // Within 0.15 of the theory: the leading error term dominates at these steps (the first
  // halving is also checked, looser, to catch a method that only looks right at one step).
  EXPECT_NEAR(order, c.expected_order, 0.15) << "errors " << e1 << " " << e2 << " " << e3;
  EXPECT_NEAR(std::log2(e1 / e2), c.expected_order, 0.3);
}

// Every fixed-step integrator of the catalogue at the order its row claims, from a step where the
// leading error term dominates: small enough for the asymptotic regime, large enough that the
// error of the finest run (h / 4) stays far above round-off (the steps this test has used for
// orders 1, 2 and 4; 0.05 for an order-3 method).
std::vector<OrderCase> everyFixedStepMethod() {
  std::vector<OrderCase> cases;
  for (const std::string& name : integratorNames(true)) {
    const int order = findIntegrator(name)->order;
    const double h = order == 1 ? 0.01 : order == 2 ? 0.02 : order == 3 ? 0.05 : 0.1;
    cases.push_back({name, order, h});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllFixedStepIntegrators, ConvergenceOrder,
                         ::testing::ValuesIn(everyFixedStepMethod()),
                         [](const auto& info) { return testing::identifier(info.param.integrator); });

// Energy of the undamped oscillator over a run: the largest relative deviation from the start.
double worstEnergyDrift(const std::string& integrator, double h, long steps, double* end_ratio) {
  Oscillator osc;
  ParticleSystem system(osc.model(), {});
  auto method = testing::integratorNamed(integrator);
  State s = system.initialState();
  const double e0 = system.energy(s)->total();
  double worst = 0.0;
  for (long n = 0; n < steps; ++n) {
    method->step(system, s, h);
    worst = std::max(worst, std::abs(system.energy(s)->total() / e0 - 1));
  }
  if (end_ratio) *end_ratio = system.energy(s)->total() / e0;
  return worst;
}

TEST(EnergyBehaviour, SymplecticMethodsKeepUndampedEnergyBoundedOver1e5Steps) {
  const double h = 0.05;  // h w0 = 0.1
  // Symplectic Euler conserves a modified energy within O(h w0) of the true one: the deviation
  // swings with amplitude about h w0 / 2 = 0.05, and never grows. Verlet's is O((h w0)^2).
  EXPECT_LT(worstEnergyDrift("symplectic-euler", h, 100000, nullptr), 0.06);
  EXPECT_LT(worstEnergyDrift("verlet", h, 100000, nullptr), 0.003);
}

TEST(EnergyBehaviour, NonSymplecticMethodsDriftAsTheirAmplificationSays) {
  const double h = 0.05, hw = 0.1;
  const long steps = 10000;
  double euler = 0, trapezoidal = 0, rk4 = 0;
  // Euler gets fewer steps: past amplitude 1 the particle would cross the anchor, where the
  // spring is no longer linear.
  const long euler_steps = 200;
  worstEnergyDrift("euler", h, euler_steps, &euler);
  worstEnergyDrift("trapezoidal", h, steps, &trapezoidal);
  worstEnergyDrift("rk4", h, steps, &rk4);
  // Energy scales with amplitude squared: (1 + (h w)^2)^n, (1 + (h w)^4 / 4)^n,
  // (1 - (h w)^6 / 72 + (h w)^8 / 576)^n.
  EXPECT_NEAR(euler, std::pow(1 + hw * hw, euler_steps), 1e-9 * euler);
  EXPECT_NEAR(trapezoidal, std::pow(1 + std::pow(hw, 4) / 4, steps), 1e-9);
  EXPECT_NEAR(rk4, std::pow(1 - std::pow(hw, 6) / 72 + std::pow(hw, 8) / 576, steps), 1e-9);
}

TEST(EnergyBehaviour, BackwardEulerAmplitudeShrinksByOneOverSqrtOnePlusHWSquaredPerStep) {
  Oscillator osc;
  ParticleSystem system(osc.model(), {});
  auto method = testing::integratorNamed("backward-euler");
  for (double h : {0.01, 0.1, 1.0}) {
    State s = system.initialState();
    const long n = 20;
    s = testing::integrate(system, *method, s, h, n);
    const double amplitude = std::hypot(s.y[3] - osc.rest_length, s.y[9] / osc.omega0());
    const double hw = h * osc.omega0();
    // One Newton step is exact on a linear spring; CG at 1e-12 leaves round-off only.
    EXPECT_NEAR(amplitude / osc.amplitude, std::pow(1 + hw * hw, -0.5 * n), 1e-9) << h;
  }
}

}  // namespace
}  // namespace mysim
