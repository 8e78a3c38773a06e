// XPBD (mysim/src/integrators/xpbd.cpp): what it must converge to.
//
//   anchor (pinned) o----/\/\/\----o particle        the oscillator of test_support.h
// ctest-label: physics
#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

namespace mysim {
namespace {

std::unique_ptr<Integrator> xpbd(int substeps, int iterations) {
  IntegratorSettings s;
  s.name = "xpbd";
  s.values = {{"substeps", substeps}, {"iterations", iterations}};
  return std::move(makeIntegrator(s).value());
}

// |u(T) - exact| of the undamped-free, drag-damped oscillator after T = 2 s at step h.
double oscillatorError(int substeps, double h) {
  testing::Oscillator osc;
  osc.drag = 0.4;
  ParticleSystem system(osc.model(), {});
  auto method = xpbd(substeps, 1);
  const long steps = std::lround(2.0 / h);
  const State s = testing::integrate(system, *method, system.initialState(), h, steps);
  return std::abs(s.y[3] - osc.rest_length - osc.displacement(2.0));
}

// One spring to a pin is one constraint: a single pass solves each substep exactly, so a substep
// is an implicit Euler step of the compliant spring and the error falls at first order in the
// substep (Macklin et al. 2016, sec. 4; 2019): halving it halves the error. Within 0.15 of order
// 1, as the convergence tests of the ODE integrators.
TEST(Xpbd, ConvergesAtFirstOrderAsSubstepsGrow) {
  const double h = 0.05;
  const double e8 = oscillatorError(8, h), e16 = oscillatorError(16, h),
               e32 = oscillatorError(32, h);
  EXPECT_NEAR(std::log2(e8 / e16), 1.0, 0.15) << e8 << " " << e16;
  EXPECT_NEAR(std::log2(e16 / e32), 1.0, 0.15) << e16 << " " << e32;
}

// Zero compliance (a stiffness no step can feel: alpha h^-2 ~ 1e-12 of the inverse masses) and
// passes enough for Gauss-Seidel to settle a 6-link chain: every link keeps its rest length while
// the chain swings under gravity (measured 1.6e-13 at 2000 passes, 4.5e-9 at 200: Gauss-Seidel
// converges linearly per pass; 1e-9 fails a projection that is wrong, or not iterated).
//
//   o--o--o--o--o--o--o   pinned at the left end, released horizontal
TEST(Xpbd, WithZeroComplianceHoldsEveryConstraint) {
  Model model;
  buildChain({.particles = 7, .rest_length = 0.1, .particle_mass = 0.01, .stiffness = 1e14}, model);
  model.pinned[0] = 1;
  model.gravity = Vec3(0, -9.8, 0);
  ParticleSystem system(model, {});
  auto method = xpbd(1, 2000);
  State s = system.initialState();
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    method->step(system, s, 0.005);
    worst = std::max(worst, system.maxStrain(s.y.head(21)));
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(s.y[3 * 6 + 1], -0.2);  // and it did swing down (the chain is 0.6 m long)
}

// XPBD's implicit substeps damp: an undamped oscillator loses energy every step (implicit Euler
// shrinks the amplitude by 1/sqrt(1 + (h w)^2) a step); it never gains.
TEST(Xpbd, LosesEnergyOnAnUndampedOscillatorAndNeverGainsIt) {
  testing::Oscillator osc;
  ParticleSystem system(osc.model(), {});
  auto method = xpbd(1, 1);
  State s = system.initialState();
  double previous = system.energy(s)->total();
  const double start = previous;
  for (int k = 0; k < 500; ++k) {
    method->step(system, s, 0.05);
    const double e = system.energy(s)->total();
    EXPECT_LE(e, previous + 1e-12) << "step " << k;
    previous = e;
  }
  EXPECT_LT(previous, 0.5 * start);
}

}  // namespace
}  // namespace mysim
