// Invariants every integrator must keep on particle systems: free fall, pins, momentum.
// ctest-label: physics
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "mysim/chain.h"
#include "test_support.h"

namespace mysim {
namespace {

class EveryIntegrator : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryIntegrator, FreeFallMatchesClosedFormWithinTheMethodsKnownError) {
  Model model;
  model.mass = Vector::Constant(1, 0.3);
  model.pinned = {0};
  model.start_position = Vector::Zero(3);
  model.start_velocity = (Vector(3) << 1.0, 2.0, 0.0).finished();
  model.gravity = Vec3(0, -9.8, 0);
  ParticleSystem system(model, {});
  auto method = testing::integratorNamed(GetParam());
  const double h = 0.01;
  const long n = 100;
  const State s = testing::integrate(system, *method, system.initialState(), h, n);
  const double t = h * n;
  const Vec3 exact = Vec3(1, 2, 0) * t + 0.5 * model.gravity * t * t;
  // Constant acceleration: methods of order >= 2 are exact; Euler lands g t h / 2 above the
  // parabola, symplectic and backward Euler the same below it (sum of n vs n - 1 kicks).
  const bool first_order = findIntegrator(GetParam())->order == 1;
  // XPBD kicks once a substep: its error is that of its substep.
  IntegratorSettings defaults;
  defaults.name = GetParam();
  const double kick = h / std::max(1.0, defaults.value("substeps"));
  const double expected_error = first_order ? 0.5 * 9.8 * t * kick : 0.0;
  EXPECT_NEAR((s.y.head<3>() - exact).norm(), expected_error, 1e-9);
  EXPECT_NEAR(s.y[4], 2 - 9.8 * t, 1e-9);  // velocity is exact for all
}

Model pinnedChain() {
  Model model;
  buildChain(
      {.particles = 6, .rest_length = 0.2, .particle_mass = 0.1, .stiffness = 100, .damping = 0.1},
      model);
  model.pinned[0] = 1;
  model.pinned[3] = 1;
  model.gravity = Vec3(0, -9.8, 0);
  return model;
}

TEST_P(EveryIntegrator, PinnedParticlesStayExactlyWhereTheSceneputsThem) {
  const Model model = pinnedChain();
  ParticleSystem system(model, {});
  auto method = testing::integratorNamed(GetParam());
  const State s = testing::integrate(system, *method, system.initialState(), 0.002, 500);
  for (int p : {0, 3}) {
    EXPECT_EQ(Vec3(s.y.segment<3>(3 * p)), Vec3(at3(model.start_position, p)));
    EXPECT_EQ(Vec3(s.y.segment<3>(18 + 3 * p)), Vec3::Zero());
  }
  EXPECT_LT(s.y[3 * 5 + 1], -0.01);  // and the free end did fall
}

TEST_P(EveryIntegrator, DrivenPinsFollowThePrescribedMotion) {
  Model model = pinnedChain();
  model.pin_motion = PinMotion{Vec3::UnitZ(), 0.1, 1.5};
  ParticleSystem system(model, {});
  auto method = testing::integratorNamed(GetParam());
  const State s = testing::integrate(system, *method, system.initialState(), 0.002, 333);
  for (int p : {0, 3}) {
    const Vec3 expected = at3(model.start_position, p) + model.pin_motion->offset(s.t);
    EXPECT_LT((Vec3(s.y.segment<3>(3 * p)) - expected).norm(), 1e-12);
    EXPECT_LT((Vec3(s.y.segment<3>(18 + 3 * p)) - model.pin_motion->velocity(s.t)).norm(), 1e-12);
  }
}

TEST_P(EveryIntegrator, MomentumIsConservedWithoutExternalForces) {
  // Three free particles on springs, spinning and stretched, no gravity, drag or pins.
  Model model;
  model.mass = (Vector(3) << 0.1, 0.2, 0.3).finished();
  model.pinned = {0, 0, 0};
  model.start_position = (Vector(9) << 0, 0, 0, 1.2, 0, 0, 0, 0.9, 0.1).finished();
  model.start_velocity = (Vector(9) << 0, -1, 0, 0, 1, 0.5, 1, 0, 0).finished();
  model.springs = {{0, 1, 1.0, 50, 0.2, SpringFamily::Custom},
                   {1, 2, 1.0, 50, 0.2, SpringFamily::Custom},
                   {0, 2, 1.0, 50, 0.2, SpringFamily::Custom}};
  ParticleSystem system(model, {});
  auto momentum = [&](const State& s) {
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < 3; ++i) p += model.mass[i] * s.y.segment<3>(9 + 3 * i);
    return p;
  };
  auto method = testing::integratorNamed(GetParam());
  const State start = system.initialState();
  const State end = testing::integrate(system, *method, start, 0.001, 1000);
  // Spring forces cancel in pairs, so every explicit stage conserves momentum to round-off.
  // Backward Euler's CG (tolerance 1e-12) leaves a residual of that relative size. XPBD's
  // velocities are position differences over h_s, their round-off growing with the substeps
  // (3.0e-10 at its default 40).
  const double bound = std::string(GetParam()) == "xpbd" ? 1e-9 : 1e-10;
  EXPECT_LT((momentum(end) - momentum(start)).norm(), bound);
}

INSTANTIATE_TEST_SUITE_P(All, EveryIntegrator, ::testing::ValuesIn(testing::particleIntegrators()),
                         testing::IntegratorParamName());

}  // namespace
}  // namespace mysim
