// Instability that levels off: a damped scene cannot gain energy, so a run whose total energy
// climbs above its lowest earlier value has gone unstable even if it never explodes.
// ctest-label: physics
#include <gtest/gtest.h>

#include "compare/engines/engine_registry.h"
#include "compare/studies/stability.h"
#include "mysim/particle_system.h"

namespace springcheck {
namespace {

const std::string kChainHanging =
    std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/matched/chain_hanging.json";

TEST(BoundedInstability, ForwardEulerThatGrowsAHundredfoldAndLevelsOffIsReportedWithItsTime) {
  const EngineRegistry registry;
  auto scene = registry.loadScene(kChainHanging);
  ASSERT_TRUE(scene) << scene.error();
  scene->integrator.name = "euler";
  scene->dt = 5e-4;
  // Without the energy-rise check the run "completes": no explosion, its kinetic energy grows
  // from millijoules to joules and levels off (the converged run ends near 1e-11 J).
  mysim::Scene unchecked = *scene;
  unchecked.limits.max_energy_rise = unchecked.limits.max_energy_rise_damped = 1e9;
  auto levelled = registry.run("mysim", unchecked);
  ASSERT_TRUE(levelled);
  ASSERT_FALSE(levelled->blowup);
  const auto& e = levelled->energies;
  const double middle = e[e.size() / 2].kinetic, end = e.back().kinetic;
  EXPECT_GT(end, 100 * middle);
  EXPECT_LT(end, 2 * e[3 * e.size() / 4].kinetic);  // levelled off: not exploding
  // With it, the run is stopped and reported, with its time, well before the end.
  auto checked = registry.run("mysim", *scene);
  ASSERT_TRUE(checked);
  ASSERT_TRUE(checked->blowup);
  EXPECT_EQ(checked->blowup->check, "energy-rise");
  EXPECT_GT(checked->blowup->time, 0.0);
  // Caught on the way up: before the kinetic energy reaches its levelled value.
  EXPECT_LT(checked->blowup->time, 0.75 * scene->duration);
  EXPECT_EQ(checked->status(), "blowup");
}

TEST(BoundedInstability, AStableRunOfTheSameDampedSceneIsNotReported) {
  const EngineRegistry registry;
  auto scene = registry.loadScene(kChainHanging);
  ASSERT_TRUE(scene);
  for (const char* integrator : {"rk4", "symplectic-euler", "backward-euler"}) {
    scene->integrator.name = integrator;
    auto run = registry.run("mysim", *scene);
    ASSERT_TRUE(run);
    EXPECT_FALSE(run->blowup) << integrator << ": " << run->blowup->check;
  }
}

// A small, strongly damped cloth: forward Euler's limit is set by the drag (h < gamma / w^2).
mysim::Scene dampedCloth() {
  mysim::Scene s;
  s.name = "damped_cloth";
  mysim::ClothScene& cloth = s.system.emplace<mysim::ClothScene>();
  cloth.shape.rows = cloth.shape.cols = 6;
  cloth.shape.particle_mass = 0.01;
  cloth.shape.structural = cloth.shape.shear = mysim::SpringParameters{20.0, 0.0};
  cloth.shape.flex = mysim::SpringParameters{2.0, 0.0};
  cloth.start.pins = {0, 5};
  s.gravity = mysim::Vec3(0, -9.8, 0);
  s.drag = 0.2;  // 20 /s
  s.integrator.name = "euler";
  s.dt = 1e-3;
  s.duration = 3.0;
  return s;
}

// Every step the stability search calls stable (over the whole run) gives a run that ends where
// the converged run ends: its final total energy is within the rise bound (2.5 % of the energy
// scale) of the converged run's, and from 0.9 of the limit down within 1 % of it: no run called
// stable keeps the joules of motion an unstable one pumps in.
TEST(BoundedInstability, EveryStepTheSearchCallsStableEndsAtTheConvergedEnergy) {
  const EngineRegistry registry;
  const mysim::Scene scene = dampedCloth();
  SceneStabilitySettings settings;
  settings.duration = scene.duration;
  const StabilityLimit limit =
      sceneStability(registry, mysim::buildModel(scene), runConfig(scene), "mysim:euler", settings);
  ASSERT_EQ(limit.status, "bracketed");
  mysim::Scene converged = scene;
  converged.integrator.name = "rk4";
  converged.dt = 1e-4;
  auto reference = registry.run("mysim", converged);
  ASSERT_TRUE(reference);
  const double e_ref = reference->energies.back().total();
  const auto bound =
      mysim::ParticleSystem(mysim::buildModel(scene), scene.limits).energyRiseLimit();
  ASSERT_TRUE(bound);
  for (double fraction : {1.0, 0.9, 0.7, 0.5}) {
    mysim::Scene s = scene;
    s.dt = limit.h_stable * fraction;
    auto run = registry.run("mysim", s);
    ASSERT_TRUE(run);
    ASSERT_FALSE(run->blowup) << "h = " << s.dt << " of " << limit.h_stable << ": "
                              << run->blowup->check << " at " << run->blowup->time;
    EXPECT_NEAR(run->energies.back().total(), e_ref,
                fraction < 1.0 ? 0.01 * std::abs(e_ref) : *bound)
        << "h = " << s.dt;
  }
}

}  // namespace
}  // namespace springcheck
