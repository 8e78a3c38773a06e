// XPBD (mysim/src/integrators/xpbd.cpp): what it must converge to.
//
//   anchor (pinned) o----/\/\/\----o particle        the oscillator of test_support.h
// ctest-label: physics
// releaseonly: the warm start against the cold form, solved to 1e-6, is 16 s under the sanitizers
// (0.7 s in Release); the warm start's code runs there in every XPBD run at its defaults
// (ShippedSceneOpening's mysim:xpbd on every shipped scene, ContactAtOneSixtieth's xpbd).
// ctest-label XpbdWarmStart: physics,releaseonly
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "mysim/cloth.h"
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

// The check cloth (16 x 16, structural and shear 100 N/m, flex 10 N/m, drag 2/s, corners
// pinned) falling from horizontal for 1 s at 1/60 s with XPBD's defaults, warm started or from
// lambda = 0; its last positions and the passes it took.
std::pair<Vector, long> fallingCloth(double warm_start, double tolerance) {
  Model model;
  const int n = 16;
  ClothShape shape{.rows = n, .cols = n, .particle_mass = 0.5 / (n * n), .hanging = false};
  shape.structural = shape.shear = SpringParameters{100.0, 0.0};
  shape.flex = SpringParameters{10.0, 0.0};
  buildCloth(shape, model);
  model.pinned[0] = model.pinned[n - 1] = 1;
  model.gravity = Vec3(0, -9.8, 0);
  model.drag = 2.0 * 0.5 / (n * n);
  ParticleSystem system(model, {});
  IntegratorSettings settings;
  settings.name = "xpbd";
  settings.values = {{"warm_start", warm_start}, {"tolerance", tolerance}};
  auto method = std::move(makeIntegrator(settings).value());
  State s = system.initialState();
  long passes = 0;
  for (int k = 0; k < 60; ++k) passes += method->step(system, s, 1.0 / 60.0).linear_iterations;
  return {s.y.head(3 * model.particleCount()), passes};
}

// Warm start (the last substep's multipliers first) is an acceleration: solved far past the
// default tolerance (1e-6) it ends where the form from lambda = 0 ends, to 2e-5 m (measured
// 4.8e-6 m mid-swing; not to round-off: XPBD's solved substep depends on its pushes' path, the
// rest bias of docs/performance.md "XPBD at rest"), in fewer passes (measured 7 274 against
// 11 743), and at the default 1 % in under half (2 507 against 6 957).
TEST(XpbdWarmStart, EndsWhereTheColdFormEndsInFewerPasses) {
  const auto [cold, cold_passes] = fallingCloth(0.0, 1e-6);
  const auto [warm, warm_passes] = fallingCloth(1.0, 1e-6);
  EXPECT_LT((cold - warm).lpNorm<Eigen::Infinity>(), 2e-5);
  EXPECT_LT(warm_passes, 0.75 * static_cast<double>(cold_passes));
  EXPECT_LT(2 * fallingCloth(1.0, 1e-2).second, fallingCloth(0.0, 1e-2).second);
}

}  // namespace
}  // namespace mysim
