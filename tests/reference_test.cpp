// The Bullet twins: built like mysim's model, and checked against closed forms.
// ctest-label: bullet,physics
#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "mysim/circle_system.h"
#include "mysim/particle_system.h"
#include "mysim/scene_file.h"
#include "mysim/simulation.h"
#include "reference/bullet_engine.h"

namespace reference {
namespace {

using mysim::Scene;

constexpr BulletEngine kAllEngines[] = {BulletEngine::Deformable, BulletEngine::Implicit,
                                        BulletEngine::Classic};

Scene loadFrom(const std::string& path) {
  auto scene = mysim::loadScene(path, {bulletSceneSection()});
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

Scene matchedScene(const std::string& name) {
  return loadFrom(std::string(SPRINGCHECK_SOURCE_DIR "/scenes/matched/") + name);
}

Scene sceneFromText(const std::string& json) {
  auto scene = mysim::parseScene(json, "inline.json", {bulletSceneSection()});
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

BulletSettings settingsOf(const Scene& scene) {
  return bulletSettings(scene.source, scene.dt, scene.integrator, scene.engine_settings);
}

auto makeStepper(const Scene& scene, BulletEngine engine) {
  return makeBulletStepper(mysim::buildModel(scene), engine, settingsOf(scene));
}

// Steps a scene in an engine by hand, calling `check` after every step.
void stepScene(const Scene& scene, BulletEngine engine,
               const std::function<void(const mysim::Model&, const mysim::State&)>& check,
               BulletSettings settings) {
  const mysim::Model model = mysim::buildModel(scene);
  auto stepper = makeBulletStepper(model, engine, settings);
  ASSERT_TRUE(stepper) << stepper.error();
  mysim::State s = mysim::ParticleSystem(model, scene.limits).initialState();
  const long steps = std::lround(scene.duration / scene.dt);
  for (long k = 0; k < steps; ++k) {
    (*stepper)->step(s, scene.dt);
    check(model, s);
  }
}
void stepScene(const Scene& scene, BulletEngine engine,
               const std::function<void(const mysim::Model&, const mysim::State&)>& check) {
  stepScene(scene, engine, check, settingsOf(scene));
}

// A whole run in an engine, recorded like any run.
mysim::RunRecord runScene(const Scene& scene, BulletEngine engine) {
  const mysim::Model model = mysim::buildModel(scene);
  auto stepper = makeBulletStepper(model, engine, settingsOf(scene));
  EXPECT_TRUE(stepper) << stepper.error();
  auto system = mysim::makeSystem(model, scene.limits);
  return mysim::simulate(*system, **stepper, system->initialState(),
                         {scene.dt, scene.duration, scene.sample_interval});
}

class EveryBulletEngine : public ::testing::TestWithParam<BulletEngine> {};

TEST_P(EveryBulletEngine, FreeFallMatchesClosedFormWithinTheSymplecticEulerOffset) {
  const Scene scene = sceneFromText(R"({
    "system": {"type": "particles", "particles": [
      {"position": [0, 0, 0], "velocity": [1, 2, 0], "mass": 0.1},
      {"position": [1, 0, 0], "velocity": [0, 0, -1], "mass": 0.2},
      {"position": [0, 1, 1], "mass": 0.3}]},
    "forces": {"gravity": [0, -9.8, 0]},
    "integrator": {"dt": 0.01, "duration": 1.0}})");
  double t = 0.0;
  mysim::State last;
  stepScene(scene, GetParam(), [&](const mysim::Model&, const mysim::State& s) {
    t = s.t;
    last = s;
  });
  ASSERT_NEAR(t, 1.0, 1e-9);
  for (int p = 0; p < 3; ++p) {
    const auto& particle = std::get<mysim::ParticlesScene>(scene.system).particles[p];
    const mysim::Vec3 exact =
        particle.position + particle.velocity * t + 0.5 * scene.gravity * t * t;
    // Every Bullet engine kicks then drifts (v += g h, x += v h): symplectic Euler, which lands
    // exactly g t h / 2 below the parabola. The classic world passes h through float (relative
    // 2e-8), hence the 1e-6 m allowance.
    const double offset = 0.5 * 9.8 * t * scene.dt;
    EXPECT_NEAR((last.y.segment<3>(3 * p) - exact).norm(), offset, 1e-6) << p;
  }
}

TEST_P(EveryBulletEngine, PinnedNodesStayExactlyWhereTheSceneputsThem) {
  Scene scene = matchedScene("chain_swing.json");
  scene.duration = 0.5;
  stepScene(scene, GetParam(), [&](const mysim::Model& model, const mysim::State& s) {
    ASSERT_EQ(mysim::Vec3(s.y.head<3>()), mysim::Vec3(model.start_position.head<3>()));
  });
}

TEST_P(EveryBulletEngine, DrivenPinsFollowThePrescribedMotion) {
  Scene scene = matchedScene("cloth_driven.json");
  scene.duration = 0.6;
  stepScene(scene, GetParam(), [&](const mysim::Model& model, const mysim::State& s) {
    for (int p : std::get<mysim::ClothScene>(scene.system).start.pins) {
      const mysim::Vec3 expected = mysim::pinnedPosition(model, p, s.t);
      ASSERT_LT((mysim::Vec3(s.y.segment<3>(3 * p)) - expected).norm(), 1e-12) << s.t;
    }
  });
}

TEST_P(EveryBulletEngine, ConstructionHoldsMysimsNodesMassesLinksAndRestLengths) {
  for (const char* name : {"chain_hanging.json", "cloth_hanging.json"}) {
    const Scene scene = matchedScene(name);
    const mysim::Model model = mysim::buildModel(scene);
    auto stepper = makeBulletStepper(model, GetParam(), settingsOf(scene));
    ASSERT_TRUE(stepper) << stepper.error();
    const btSoftBody& body = (*stepper)->body();
    ASSERT_EQ(body.m_nodes.size(), model.particleCount()) << name;
    ASSERT_EQ(body.m_links.size(), static_cast<int>(model.springs.size())) << name;
    double bullet_mass = 0.0, mysim_mass = 0.0;
    for (int p = 0; p < model.particleCount(); ++p) {
      EXPECT_EQ(body.m_nodes[p].m_im == 0, static_cast<bool>(model.pinned[p]));
      if (body.m_nodes[p].m_im > 0) bullet_mass += 1.0 / body.m_nodes[p].m_im;
      if (!model.pinned[p]) mysim_mass += model.mass[p];
    }
    EXPECT_NEAR(bullet_mass, mysim_mass, 1e-12 * mysim_mass) << name;
    for (int k = 0; k < body.m_links.size(); ++k) {
      const btSoftBody::Link& link = body.m_links[k];
      EXPECT_EQ(link.m_n[0] - &body.m_nodes[0], model.springs[k].i);
      EXPECT_EQ(link.m_n[1] - &body.m_nodes[0], model.springs[k].j);
      EXPECT_DOUBLE_EQ(link.m_rl, model.springs[k].rest_length) << name << " link " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, EveryBulletEngine, ::testing::ValuesIn(kAllEngines),
                         [](const auto& info) {
                           std::string name = bulletEngineName(info.param);
                           std::erase(name, '-');
                           return name;
                         });

// Largest |y_j - closed form| over the chain after the scene's 20 s, and the end's closed-form
// stretch below its unstretched position.
std::pair<double, double> chainSagError(BulletEngine engine) {
  const Scene scene = matchedScene("chain_hanging.json");
  const mysim::RunRecord record = runScene(scene, engine);
  const auto& c = std::get<mysim::ChainScene>(scene.system).shape;
  const int n = c.particles - 1;
  const double w = c.particle_mass * 9.8 / c.stiffness;
  double worst = 0.0;
  for (int j = 1; j <= n; ++j) {
    const double exact = -(j * c.rest_length + w * j * (2 * n - j + 1) / 2.0);
    worst = std::max(worst, std::abs(record.frames.back()(j, 1) - exact));
  }
  return {worst, w * n * (n + 1) / 2.0};
}

TEST(BulletChainAtRest, DeformableAndImplicitMatchClosedFormSag) {
  for (BulletEngine engine : {BulletEngine::Deformable, BulletEngine::Implicit}) {
    // Same force law and masses as the closed form; after 20 s of drag at 1 /s the slowest mode
    // holds e^-10 of the ~0.35 m start displacement (1.6e-5 m). 1e-4 m leaves room for that.
    EXPECT_LT(chainSagError(engine).first, 1e-4) << bulletEngineName(engine);
  }
}

TEST(BulletChainAtRest, ClassicSagErrorIsMeasuredAndBounded) {
  const auto [error, stretch] = chainSagError(BulletEngine::Classic);
  // Position-based links match a spring only approximately (docs/reference.md): measured 0.044 m
  // short of the 0.353 m stretch (12 %), the same at 1, 10 and 50 iterations. Fail past 15 %.
  RecordProperty("classic_sag_error_m", std::to_string(error));
  std::printf("bullet-classic chain sag error: %.4f m of %.4f m (%.1f %%)\n", error, stretch,
              100 * error / stretch);
  EXPECT_LT(error, 0.15 * stretch);
  EXPECT_GT(error, 0.0);
}

TEST(BulletSphere, ClassicAndDeformableKeepPenetrationWithinBound) {
  const Scene scene = matchedScene("cloth_on_sphere.json");
  for (BulletEngine engine : {BulletEngine::Deformable, BulletEngine::Classic}) {
    double deepest = 0.0;
    stepScene(scene, engine, [&](const mysim::Model&, const mysim::State& s) {
      for (int p = 0; p < 144; ++p) {
        deepest = std::max(deepest, -mysim::signedDistance(scene.colliders.at(0), mysim::at3(s.y, p)));
      }
    });
    std::printf("%s deepest penetration: %.5f m\n", bulletEngineName(engine), deepest);
    // 5 mm: the cloth's spacing is 91 mm; Bullet resolves contacts against a sparse signed
    // distance field (voxels of radius / 10 = 30 mm here) and, in the deformable world, as
    // velocity constraints, so nodes may sit a little inside between corrections. mysim's
    // projection keeps every node out exactly (sphere_test.cpp).
    EXPECT_LT(deepest, 0.005) << bulletEngineName(engine);
  }
}

TEST(BulletRefusals, ClassicNamesTheFieldAndWhatToChange) {
  const Scene seed_cloth = loadFrom(SPRINGCHECK_SOURCE_DIR "/scenes/seed/cloth.json");
  auto classic = makeStepper(seed_cloth, BulletEngine::Classic);
  ASSERT_FALSE(classic);
  EXPECT_NE(classic.error().find("bullet-classic: system.structural.damping"), std::string::npos)
      << classic.error();
  EXPECT_NE(classic.error().find("set it to 0"), std::string::npos) << classic.error();

  const Scene uneven = sceneFromText(R"({
    "system": {"type": "particles", "particles": [
      {"position": [0, 0, 0], "mass": 0.1}, {"position": [1, 0, 0], "mass": 0.2}]},
    "forces": {"drag": 0.01}, "integrator": {"dt": 0.01, "duration": 1.0}})");
  auto drag = makeStepper(uneven, BulletEngine::Classic);
  ASSERT_FALSE(drag);
  EXPECT_NE(drag.error().find("bullet-classic: forces.drag"), std::string::npos) << drag.error();
}

// Every seed scene (per-family stiffness, spring damping, wind, swing, sphere, the circle) builds
// in both deformable engines: nothing is refused.
TEST(EverySeedScene, BuildsInBothDeformableEngines) {
  int scenes = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(SPRINGCHECK_SOURCE_DIR "/scenes/seed")) {
    const Scene scene = loadFrom(entry.path().string());
    for (BulletEngine engine : {BulletEngine::Deformable, BulletEngine::Implicit}) {
      auto stepper = makeStepper(scene, engine);
      EXPECT_TRUE(stepper) << entry.path() << ": " << (stepper ? "" : stepper.error());
    }
    ++scenes;
  }
  EXPECT_GE(scenes, 7);
}

// The per-link spring force, given the parameters Bullet's own btDeformableMassSpringForce holds
// (one stiffness for non-bending links, one for bending links, one damping), must produce the same
// trajectory: that is what makes it trustworthy where Bullet's force cannot go. A damped 6 x 6
// cloth with all three families falls for 0.5 s, in explicit and in implicit mode.
TEST(PerLinkSpringForce, MatchesBulletsMassSpringForceToRoundOff) {
  const Scene scene = sceneFromText(R"({
    "system": {"type": "cloth", "rows": 6, "cols": 6, "width": 0.5, "height": 0.5,
               "particle_mass": 0.01, "structural": {"stiffness": 40, "damping": 0.02},
               "shear": {"stiffness": 40, "damping": 0.02}, "flex": {"stiffness": 4, "damping": 0.02}},
    "forces": {"gravity": [0, -9.8, 0]},
    "integrator": {"name": "backward-euler", "dt": 0.002, "duration": 0.5, "cg_tolerance": 1e-10}})");
  for (BulletEngine engine : {BulletEngine::Deformable, BulletEngine::Implicit}) {
    std::vector<mysim::State> own, ours;
    stepScene(scene, engine, [&](const mysim::Model&, const mysim::State& s) { own.push_back(s); });
    BulletSettings per_link = settingsOf(scene);
    per_link.force_per_link_springs = true;
    stepScene(
        scene, engine, [&](const mysim::Model&, const mysim::State& s) { ours.push_back(s); },
        per_link);
    ASSERT_EQ(own.size(), ours.size());
    double worst = 0.0, travel = 0.0;
    for (std::size_t k = 0; k < own.size(); ++k) {
      worst = std::max(worst, (own[k].y - ours[k].y).cwiseAbs().maxCoeff());
      travel = std::max(travel, (own[k].y - own[0].y).cwiseAbs().maxCoeff());
    }
    // Round-off: the two forces sum the same terms in the same order except for the direction
    // (normalized() against a division), a few ulps a step; over 250 steps of a cloth that moved
    // `travel` (~1 m), 1e-9 of it. A wrong stiffness, damping or differential is off by 1e-3+.
    std::printf("%s: per-link vs Bullet's force, largest difference %.3g (travel %.3g)\n",
                bulletEngineName(engine), worst, travel);
    EXPECT_LT(worst, 1e-9 * std::max(1.0, travel)) << bulletEngineName(engine);
    EXPECT_GT(travel, 0.05);  // the cloth really moved
  }
}

// The circle runs in Bullet as its mechanical twin. bullet-deformable steps it with symplectic
// Euler, so it must agree with mysim's symplectic Euler on the same twin to round-off.
TEST(CircleInBullet, DeformableTwinEqualsMysimSymplecticEulerOnTheTwin) {
  const Scene circle = sceneFromText(
      R"({"system": {"type": "circle", "start": [0.6, 0.8]}, "integrator": {"name": "rk4", "dt": 0.05, "duration": 6.3}})");
  const mysim::RunRecord bullet = runScene(circle, BulletEngine::Deformable);
  ASSERT_FALSE(bullet.blowup);
  // The twin's spring has rest length 0, so strain (l / rest - 1) means nothing there.
  mysim::ParticleSystem twin(mysim::circleTwin(mysim::buildModel(circle)),
                             {.max_strain = std::numeric_limits<double>::infinity()});
  mysim::IntegratorStepper symplectic(twin, std::move(mysim::makeIntegrator({.name = "symplectic-euler"}).value()));
  const mysim::RunRecord own =
      mysim::simulate(twin, symplectic, twin.initialState(), {circle.dt, circle.duration, 0.0});
  ASSERT_EQ(bullet.frames.size(), own.frames.size());
  for (std::size_t f = 0; f < own.frames.size(); ++f) {
    const Eigen::Vector2d expected = own.frames[f].row(mysim::kCircleTwinParticle).head<2>();
    EXPECT_LT((bullet.frames[f].row(0).head<2>().transpose() - expected).norm(), 1e-12) << f;
  }
  // And it is the circle: symplectic Euler keeps the radius within h of 1 (its modified energy).
  EXPECT_NEAR(bullet.frames.back().row(0).head<2>().norm(), 1.0, circle.dt);
}

}  // namespace
}  // namespace reference
