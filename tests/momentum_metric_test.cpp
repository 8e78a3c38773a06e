// Momentum drift: zero where the model conserves momentum, found where a run breaks it, and not
// reported where the model itself does not conserve it.
// ctest-label: physics
#include "compare/metrics/momentum_metric.h"

#include <gtest/gtest.h>

#include "compare/engines/engine_registry.h"

namespace springcheck {
namespace {

// Two unequal masses on a stretched spring, spinning and drifting, under gravity.
mysim::Scene spinningPair(const std::string& integrator) {
  mysim::Scene s;
  s.name = "pair";
  mysim::ParticlesScene& pair = s.system.emplace<mysim::ParticlesScene>();
  pair.particles = {{mysim::Vec3(-0.2, 0, 0), mysim::Vec3(0.1, -0.6, 0.2), 0.3, false},
                    {mysim::Vec3(0.2, 0, 0), mysim::Vec3(0.3, 0.6, 0.1), 0.1, false}};
  pair.springs = {{.i = 0, .j = 1, .rest_length = 0.3, .stiffness = 40.0}};
  s.gravity = mysim::Vec3(0, -9.8, 0);
  s.integrator.name = integrator;
  s.dt = 1e-3;
  s.duration = 2.0;
  return s;
}

TEST(MomentumDrift, SymplecticEulerKeepsBothMomentaOfAFreeBodyUnderGravity) {
  const mysim::Scene scene = spinningPair("symplectic-euler");
  auto run = EngineRegistry().run("mysim", scene);
  ASSERT_TRUE(run);
  const auto d = momentumDrift(mysim::buildModel(scene), *run);
  ASSERT_TRUE(d);
  EXPECT_LT(d->linear, 1e-12);   // gravity's M g t taken off exactly
  EXPECT_LT(d->angular, 1e-12);  // about the centre of mass
}

TEST(MomentumDrift, BackwardEulerLosesAngularMomentumWithTheEnergyItDamps) {
  mysim::Scene scene = spinningPair("backward-euler");
  scene.integrator.cg_tolerance = 1e-12;
  auto run = EngineRegistry().run("mysim", scene);
  ASSERT_TRUE(run);
  const auto d = momentumDrift(mysim::buildModel(scene), *run);
  ASSERT_TRUE(d);
  EXPECT_LT(d->linear, 1e-9);
  EXPECT_GT(d->angular, 1e-4);
}

TEST(MomentumDrift, AnImpulseInTheRecordIsFound) {
  const mysim::Scene scene = spinningPair("symplectic-euler");
  auto run = EngineRegistry().run("mysim", scene);
  ASSERT_TRUE(run);
  // 0.01 m/s more on particle 1 from the middle frame on: a 0.001 kg m/s push.
  for (std::size_t f = run->frames.size() / 2; f < run->frames.size(); ++f)
    run->frames[f](1, 3) += 0.01;
  const auto d = momentumDrift(mysim::buildModel(scene), *run);
  ASSERT_TRUE(d);
  EXPECT_GT(d->linear, 1e-4);
}

TEST(MomentumDrift, NotReportedWherePinsOrDragActFromOutside) {
  mysim::Scene pinned = spinningPair("rk4");
  std::get<mysim::ParticlesScene>(pinned.system).particles[0].pinned = true;
  mysim::Scene dragged = spinningPair("rk4");
  dragged.drag = 0.1;
  for (const mysim::Scene& scene : {pinned, dragged}) {
    auto run = EngineRegistry().run("mysim", scene);
    ASSERT_TRUE(run);
    EXPECT_FALSE(momentumDrift(mysim::buildModel(scene), *run));
  }
}

}  // namespace
}  // namespace springcheck
