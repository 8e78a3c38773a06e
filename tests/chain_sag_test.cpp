// A vertical chain of N free masses under a pin, at rest, against the closed form
//   y_j = -[ j L0 + (m g / k) j (2N - j + 1) / 2 ]:
// spring j carries the weight of the N - j + 1 masses below it.
//
//   o  pin (0, 0)
//   |
//   o  j = 1
//   |
//   o  j = 2 ... j = N
// ctest-label: physics
#include <gtest/gtest.h>

#include "mysim/chain.h"
#include "test_support.h"

namespace mysim {
namespace {

constexpr int kFree = 8;
constexpr double kRest = 0.1, kMass = 0.05, kStiffness = 50.0, kGravity = 9.8;

Model verticalChain() {
  Model model;
  buildChain({.particles = kFree + 1,
              .rest_length = kRest,
              .particle_mass = kMass,
              .stiffness = kStiffness,
              .damping = 0.5,
              .direction = -Vec3::UnitY()},
             model);
  model.pinned[0] = 1;
  model.gravity = Vec3(0, -kGravity, 0);
  model.drag = 0.05;
  return model;
}

double closedFormY(int j) {
  return -(j * kRest + (kMass * kGravity / kStiffness) * j * (2 * kFree - j + 1) / 2.0);
}

class ChainAtRest : public ::testing::TestWithParam<std::pair<std::string, double>> {};

TEST_P(ChainAtRest, MatchesClosedFormSag) {
  const auto& [integrator, h] = GetParam();
  ParticleSystem system(verticalChain(), {});
  auto method = testing::integratorNamed(integrator);
  const State s =
      testing::integrate(system, *method, system.initialState(), h, std::lround(30 / h));
  for (int j = 1; j <= kFree; ++j) {
    // After 30 s the slowest mode (damped at rate >= drag / 2m = 0.5 /s) has decayed by e^-15
    // of an initial sag of ~0.3 m: below 1e-7 m.
    EXPECT_NEAR(s.y[3 * j + 1], closedFormY(j), 1e-6) << integrator << " particle " << j;
    EXPECT_NEAR(s.y[3 * j], 0.0, 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(ExplicitAndImplicit, ChainAtRest,
                         ::testing::Values(std::pair{"rk4", 0.005},
                                           std::pair{"backward-euler", 0.05},
                                           std::pair{"verlet", 0.002}),
                         [](const auto& info) { return testing::identifier(info.param.first); });

}  // namespace
}  // namespace mysim
