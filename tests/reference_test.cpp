// The Bullet twins: built like mysim's model, and checked against closed forms.
#include <BulletSoftBody/btSoftBody.h>
#include <gtest/gtest.h>

#include "mysim/scene_file.h"
#include "reference/bullet_engine.h"

namespace reference {
namespace {

using mysim::Scene;

constexpr BulletEngine kAllEngines[] = {BulletEngine::Deformable, BulletEngine::Implicit,
                                        BulletEngine::Classic};

Scene matchedScene(const std::string& name) {
  auto scene = mysim::loadScene(std::string(SPRINGCHECK_SOURCE_DIR "/scenes/matched/") + name);
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

Scene sceneFromText(const std::string& json) {
  auto scene = mysim::parseScene(json, "inline.json");
  EXPECT_TRUE(scene) << scene.error();
  return *scene;
}

// Steps a scene in an engine by hand, calling `check` after every step.
void stepScene(
    const Scene& scene, BulletEngine engine,
    const std::function<void(const mysim::ParticleSystem&, const mysim::State&)>& check) {
  mysim::ParticleSystem system(mysim::buildModel(scene), scene.limits);
  auto stepper = makeBulletStepper(scene, system.model(), engine);
  ASSERT_TRUE(stepper) << stepper.error();
  mysim::State s = system.initialState();
  const long steps = std::lround(scene.duration / scene.dt);
  for (long k = 0; k < steps; ++k) {
    (*stepper)->step(system, s, scene.dt);
    check(system, s);
  }
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
  stepScene(scene, GetParam(), [&](const mysim::ParticleSystem&, const mysim::State& s) {
    t = s.t;
    last = s;
  });
  ASSERT_NEAR(t, 1.0, 1e-9);
  for (int p = 0; p < 3; ++p) {
    const auto& particle = scene.particles[p];
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
  stepScene(scene, GetParam(), [&](const mysim::ParticleSystem& system, const mysim::State& s) {
    ASSERT_EQ(mysim::Vec3(s.y.head<3>()), mysim::Vec3(system.model().start_position.head<3>()));
  });
}

TEST_P(EveryBulletEngine, DrivenPinsFollowThePrescribedMotion) {
  Scene scene = matchedScene("cloth_driven.json");
  scene.duration = 0.6;
  stepScene(scene, GetParam(), [&](const mysim::ParticleSystem& system, const mysim::State& s) {
    for (int p : scene.pins) {
      const mysim::Vec3 expected = system.pinPosition(p, s.t);
      ASSERT_LT((mysim::Vec3(s.y.segment<3>(3 * p)) - expected).norm(), 1e-12) << s.t;
    }
  });
}

TEST_P(EveryBulletEngine, ConstructionHoldsMysimsNodesMassesLinksAndRestLengths) {
  for (const char* name : {"chain_hanging.json", "cloth_hanging.json"}) {
    const Scene scene = matchedScene(name);
    const mysim::Model model = mysim::buildModel(scene);
    auto stepper = makeBulletStepper(scene, model, GetParam());
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
  auto record = runBullet(scene, engine);
  EXPECT_TRUE(record) << record.error();
  const auto& c = scene.chain;
  const int n = c.particles - 1;
  const double w = c.particle_mass * 9.8 / c.stiffness;
  double worst = 0.0;
  for (int j = 1; j <= n; ++j) {
    const double exact = -(j * c.rest_length + w * j * (2 * n - j + 1) / 2.0);
    worst = std::max(worst, std::abs(record->frames.back()(j, 1) - exact));
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
    stepScene(scene, engine, [&](const mysim::ParticleSystem&, const mysim::State& s) {
      deepest = std::max(deepest, mysim::deepestPenetration(*scene.sphere, s.y.head(3 * 144)));
    });
    std::printf("%s deepest penetration: %.5f m\n", bulletEngineName(engine), deepest);
    // 5 mm: the cloth's spacing is 91 mm; Bullet resolves contacts against a sparse signed
    // distance field (voxels of radius / 10 = 30 mm here) and, in the deformable world, as
    // velocity constraints, so nodes may sit a little inside between corrections. mysim's
    // projection keeps every node out exactly (sphere_test.cpp).
    EXPECT_LT(deepest, 0.005) << bulletEngineName(engine);
  }
}

TEST(BulletRefusals, NameTheEngineAndTheField) {
  const Scene seed_cloth = [] {
    auto s = mysim::loadScene(SPRINGCHECK_SOURCE_DIR "/scenes/seed/cloth.json");
    return *s;
  }();
  const mysim::Model model = mysim::buildModel(seed_cloth);
  auto deformable = makeBulletStepper(seed_cloth, model, BulletEngine::Deformable);
  ASSERT_FALSE(deformable);
  EXPECT_NE(deformable.error().find("bullet-deformable: system.shear.stiffness"), std::string::npos)
      << deformable.error();
  auto classic = makeBulletStepper(seed_cloth, model, BulletEngine::Classic);
  ASSERT_FALSE(classic);
  EXPECT_NE(classic.error().find("bullet-classic: system.structural.damping"), std::string::npos)
      << classic.error();

  const Scene uneven = sceneFromText(R"({
    "system": {"type": "particles", "particles": [
      {"position": [0, 0, 0], "mass": 0.1}, {"position": [1, 0, 0], "mass": 0.2}]},
    "forces": {"drag": 0.01}, "integrator": {"dt": 0.01, "duration": 1.0}})");
  auto drag = makeBulletStepper(uneven, mysim::buildModel(uneven), BulletEngine::Classic);
  ASSERT_FALSE(drag);
  EXPECT_NE(drag.error().find("bullet-classic: forces.drag"), std::string::npos) << drag.error();

  const Scene circle =
      sceneFromText(R"({"system": {"type": "circle"}, "integrator": {"dt": 0.1, "duration": 1}})");
  auto run = runBullet(circle, BulletEngine::Implicit);
  ASSERT_FALSE(run);
  EXPECT_NE(run.error().find("bullet-implicit: system.type"), std::string::npos) << run.error();
}

}  // namespace
}  // namespace reference
