// Self-collision: a cloth that folds onto itself never crosses itself with it on (0 crossing
// triangle pairs at every frame, no node nearer a triangle than most of the thickness), in every
// stable mysim integrator and in bullet-deformable; with it off the metric finds the crossings,
// so the metric is tested both ways. The proximity queries against brute force.
// The whole runs (every integrator, every height, Bullet) are slow under the sanitizers (156 s for
// the integrators alone): the Release pass runs them; the sanitizer pass runs SelfCollisionOpening,
// the fold's first crossings in one integrator, which reaches the same code.
// ctest-label: physics,bullet,slow
// ctest-label SelfCollisionOpening: physics
// ctest-label SelfCollisionInput: validation,bullet,external
// ctest-label Proximity: unit
#include <gtest/gtest.h>

#include <random>

#include "compare/engines/engine_registry.h"
#include "compare/metrics/self_contact_metric.h"
#include "mysim/integrator.h"
#include "mysim/proximity.h"
#include "mysim/scene_file.h"
#include "contact_scenes.h"
#include "source_root.h"

namespace springcheck {
namespace {

// How near the thickness the nearest approach must stay with self-collision on: three passes of
// pushes leave pairs at 0.89 to 0.97 of it in the fold (XPBD 4.47 mm, symplectic Euler 4.79 mm of
// 5 mm), bullet-deformable 0.60 under the wall; 0.5 fails a contact lost, not a pass short.
constexpr double kKeptApart = 0.5;

SelfContact selfContactOf(const EngineRegistry& registry, const std::string& spec, const mysim::Scene& scene) {
  auto run = registry.run(spec, scene);
  EXPECT_TRUE(run) << spec << ": " << run.error().message;
  EXPECT_FALSE(run->blowup) << spec << ": blew up at " << run->blowup->time << ": " << run->blowup->detail;
  const auto contact = selfContactOverRun(mysim::buildModel(scene), *run);
  EXPECT_TRUE(contact);
  return contact.value_or(SelfContact{});
}

// Forward Euler and mysim's trapezoidal rule (Heun's explicit method) are left out: both gain
// energy on undamped springs at any step and blow up on the fold without self-collision too.
TEST(SelfCollision, AClothFoldedOntoTheGroundNeverCrossesItselfInEveryStableIntegrator) {
  const EngineRegistry registry;
  for (const std::string& integrator : mysim::integratorNames()) {
    if (integrator == "euler" || integrator == "trapezoidal") continue;
    mysim::Scene scene = test::contactScene("cloth_fold_on_ground");
    scene.integrator.name = integrator;
    const SelfContact c = selfContactOf(registry, "mysim", scene);
    EXPECT_EQ(c.intersections.value_or(-1), 0) << integrator << ": first at t = " << c.intersections_time;
    ASSERT_TRUE(c.distance_min) << integrator;
    EXPECT_GT(*c.distance_min, kKeptApart * *scene.self_collision_thickness) << integrator;
  }
}

// The fold up to its first crossings without self-collision (0.95 s): none with it, some without.
TEST(SelfCollisionOpening, TheFoldsFirstLayersStayApartWithItAndCrossWithout) {
  const EngineRegistry registry;
  mysim::Scene scene = test::contactScene("cloth_fold_on_ground");
  scene.duration = 0.95;
  const SelfContact on = selfContactOf(registry, "mysim", scene);
  EXPECT_EQ(on.intersections.value_or(-1), 0);
  EXPECT_GT(on.distance_min.value_or(0.0), kKeptApart * *scene.self_collision_thickness);
  scene.self_collision_thickness.reset();
  EXPECT_GT(selfContactOf(registry, "mysim", scene).intersections.value_or(0), 0);
}

// Other heights and thicknesses than the shipped scene's, with and without self-collision.
TEST(SelfCollision, OtherHeightsAndThicknessesHoldAndTheMetricFindsTheCrossingsWithoutIt) {
  const EngineRegistry registry;
  for (double lift : {0.1, 0.6}) {
    for (double thickness : {0.003, 0.008}) {
      mysim::Scene scene = test::contactScene("cloth_fold_on_ground");
      std::get<mysim::ClothScene>(scene.system).shape.origin.y() = 1.0 + lift;  // the lower edge `lift` above the ground
      scene.self_collision_thickness = thickness;
      const SelfContact on = selfContactOf(registry, "mysim", scene);
      EXPECT_EQ(on.intersections.value_or(-1), 0) << "lift " << lift << ", thickness " << thickness;
      EXPECT_GT(on.distance_min.value_or(0.0), kKeptApart * thickness) << "lift " << lift;
      scene.self_collision_thickness.reset();
      const SelfContact off = selfContactOf(registry, "mysim", scene);
      EXPECT_GT(off.intersections.value_or(0), 0) << "without self-collision, lift " << lift;
    }
  }
}

TEST(SelfCollision, TheShippedScenesWithoutItPassThroughThemselvesAndWithItDoNot) {
  const EngineRegistry registry;
  EXPECT_GT(selfContactOf(registry, "mysim", test::contactScene("cloth_fold_without_self_collision")).intersections.value_or(0), 0);
  mysim::Scene wall = test::contactScene("cloth_over_thin_wall");
  EXPECT_EQ(selfContactOf(registry, "mysim", wall).intersections.value_or(-1), 0);
  wall.self_collision_thickness.reset();
  EXPECT_GT(selfContactOf(registry, "mysim", wall).intersections.value_or(0), 0) << "the skirts cross";
  mysim::Scene pile = test::contactScene("chain_pile");
  const double thickness = *pile.self_collision_thickness;
  EXPECT_GT(selfContactOf(registry, "mysim", pile).distance_min.value_or(0.0), kKeptApart * thickness);
  pile.self_collision_thickness.reset();
  EXPECT_LT(selfContactOf(registry, "mysim", pile).distance_min.value_or(1.0), 0.1 * thickness)
      << "without self-collision the links pass through one another";
}

// Bullet's own face-face self-collision (docs/reference.md): the deformable solver keeps the fold
// and the skirts apart; the implicit mode lets 3 pairs cross in the fold (measured), bound 10.
TEST(SelfCollision, BulletDeformableKeepsTheFoldApartAndItsImplicitModeLeaksAFewPairs) {
  const EngineRegistry registry;
  for (const char* name : {"cloth_fold_on_ground", "cloth_over_thin_wall"}) {
    EXPECT_EQ(selfContactOf(registry, "bullet-deformable", test::contactScene(name)).intersections.value_or(-1), 0) << name;
  }
  EXPECT_LE(selfContactOf(registry, "bullet-implicit", test::contactScene("cloth_fold_on_ground")).intersections.value_or(99), 10);
}

TEST(SelfCollisionInput, ABadThicknessOrASystemWithoutAMeshIsRefusedNamingTheField) {
  EngineRegistry registry;
  ASSERT_TRUE(registry.addEnginesFile(test::kRoot + "/examples/external/engines.json"));
  mysim::Scene scene = test::contactScene("cloth_fold_on_ground");
  scene.self_collision_thickness = 0.2;  // more than the 1/11 m cell
  auto thick = registry.run("mysim", scene);
  ASSERT_FALSE(thick);
  EXPECT_NE(thick.error().message.find("system.self_collision.thickness"), std::string::npos) << thick.error().message;
  for (const char* engine : {"bullet-classic", "pysim"}) {
    auto refused = registry.run(engine, test::contactScene("cloth_fold_on_ground"));
    ASSERT_FALSE(refused) << engine;
    EXPECT_EQ(refused.error().kind, EngineError::Kind::Refused) << engine;
    EXPECT_NE(refused.error().message.find("self"), std::string::npos) << refused.error().message;
  }
  for (const char* thickness : {"0", "-0.01", "\"thin\""}) {
    auto parsed = mysim::parseScene(std::string(R"({"system": {"type": "chain", "particles": 3, "rest_length": 0.1,
      "particle_mass": 0.1, "stiffness": 10, "self_collision": {"thickness": )") + thickness + R"(}},
      "integrator": {"name": "rk4", "dt": 0.01, "duration": 0.1}})", "bad_self.json");
    ASSERT_FALSE(parsed) << thickness;
    EXPECT_NE(parsed.error().find("bad_self.json: system.self_collision.thickness"), std::string::npos) << parsed.error();
  }
  auto particles = mysim::parseScene(R"({"system": {"type": "particles", "particles": [{"position": [0, 0, 0], "mass": 1}],
      "self_collision": {"thickness": 0.01}}, "integrator": {"name": "rk4", "dt": 0.01, "duration": 0.1}})", "p.json");
  ASSERT_TRUE(particles) << particles.error();
  auto run = registry.run("mysim", *particles);
  ASSERT_FALSE(run);
  EXPECT_NE(run.error().message.find("p.json: system.self_collision"), std::string::npos) << run.error().message;
}

// The nearest points against the best of many random points on the pieces, and the crossing
// test against two triangles placed through and beside each other.
TEST(Proximity, NearestPointsAreNoFartherThanAnySampledPairAndCrossingsAreFound) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  auto point = [&] { return mysim::Vec3(u(random), u(random), u(random)); };
  for (int trial = 0; trial < 200; ++trial) {
    const mysim::Vec3 p = point(), a = point(), b = point(), c = point(), q = point(), r = point();
    const mysim::Vec3 w = mysim::closestOnTriangle(p, a, b, c);
    const double found = (p - (w[0] * a + w[1] * b + w[2] * c)).norm();
    const auto st = mysim::closestOnSegments(a, b, q, r);
    const double segments = ((a + st.s * (b - a)) - (q + st.t * (r - q))).norm();
    for (int k = 0; k < 200; ++k) {
      double s = unit(random), t = unit(random);
      if (s + t > 1) s = 1 - s, t = 1 - t;
      EXPECT_LE(found, (p - (a + s * (b - a) + t * (c - a))).norm() + 1e-12);
      EXPECT_LE(segments, ((a + s * (b - a)) - (q + t * (r - q))).norm() + 1e-12);
    }
  }
  const mysim::Vec3 flat[3] = {{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}};
  const mysim::Vec3 through[3] = {{0, -1, 0}, {0, 1, 0}, {0, 1, 0.5}};
  const mysim::Vec3 beside[3] = {{3, -1, 0}, {3, 1, 0}, {3, 1, 0.5}};
  EXPECT_TRUE(mysim::trianglesIntersect(flat, through));
  EXPECT_FALSE(mysim::trianglesIntersect(flat, beside));
}

}  // namespace
}  // namespace springcheck
