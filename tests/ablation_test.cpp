// Model only what a scene requires (compare/studies/ablation.h): a term that cannot matter is
// found not to, and the cantilever's bending is found to matter.
// ctest-label: physics
// releaseonly: the cantilever's ablation is 30 s under the sanitizers (8 s in Release); the same
// ablation code runs there in the suite Ablation (the cable and the cloth, under a second).
// ctest-label AblationOfTheCantilever: physics,releaseonly
#include "compare/studies/ablation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compare/metrics/elastic_catenary.h"
#include "compare/metrics/heavy_elastica.h"
#include "per_test_file.h"

namespace springcheck {
namespace {

const std::string kScenes = std::string(SPRINGCHECK_SOURCE_DIR) + "/scenes/material/";

const AblationRun* without(const Ablation& a, const std::string& term) {
  for (const AblationRun& r : a.without) {
    if (r.term == term) return &r;
  }
  return nullptr;
}

TradeSetup setup(int resolution, const std::string& integrator, double dt) {
  TradeSetup s;
  s.resolution = resolution;
  s.engine = "mysim";
  s.integrator = integrator;
  s.dt = dt;
  return s;
}

// The shipped cable with a ground plane 10 m below it, which it never reaches: taking the
// collider out changes the sag by nothing at all, so it can go; taking the damping out leaves a
// cable that swings on and does not settle, so it cannot.
std::expected<Ablation, std::string> ablateCableOverGround(const nlohmann::json& needs) {
  std::ifstream in(kScenes + "cable_catenary.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["colliders"] = {{{"type", "plane"}, {"point", {0, -10, 0}}, {"normal", {0, 1, 0}}}};
  if (!needs.is_null()) scene["needs"] = needs;
  const std::string path = test_support::perTestJsonPath("cable_over_ground");
  std::ofstream(path) << scene.dump();
  const double sag = levelElasticCatenary(1.0, 1.0, 0.05 * 9.8, 50.0).midspan_sag;
  return ablate(EngineRegistry(), path, setup(10, "backward-euler", 0.004), "sag_lowest", sag,
                0.01 * sag);
}

TEST(Ablation, AColliderTheClothNeverReachesDoesNotMatter) {
  const auto a = ablateCableOverGround(nullptr);
  ASSERT_TRUE(a) << a.error();
  ASSERT_TRUE(a->full.within) << a->full.status;
  const AblationRun* ground = without(*a, "colliders");
  ASSERT_TRUE(ground && ground->value);
  EXPECT_EQ(*ground->value, *a->full.value);
  EXPECT_TRUE(ground->within);
  const AblationRun* damping = without(*a, "damping");
  ASSERT_TRUE(damping);
  EXPECT_FALSE(damping->settled);
  ASSERT_TRUE(a->cheapest);
  EXPECT_EQ(a->cheapest->term, "colliders");
}

// The same scene declaring it needs its ground (`needs`, model_terms.h): the ablation still
// measures that the ground changes nothing, but keeps it, so no cheaper model is proposed.
TEST(Ablation, ATermTheSceneDeclaresIsKept) {
  const auto a = ablateCableOverGround(nlohmann::json::array({"colliders"}));
  ASSERT_TRUE(a) << a.error();
  const AblationRun* ground = without(*a, "colliders");
  ASSERT_TRUE(ground);
  EXPECT_TRUE(ground->within);
  EXPECT_TRUE(ground->declared);
  EXPECT_FALSE(without(*a, "damping")->declared);
  EXPECT_FALSE(a->cheapest) << a->cheapest->term;
}

// The shipped cantilever without bending hangs from its clamp as a membrane: its tip drops far
// beyond 1 % of the elastica's, so bending is a term the scene requires.
TEST(AblationOfTheCantilever, BendingIsNeeded) {
  const double L = 0.1, load = 0.2 * 9.8 * L * L * L / 2.45e-4;
  const double drop = heavyElastica(load).drop * L;
  const auto a = ablate(EngineRegistry(), kScenes + "cantilever_strip.json",
                        setup(8, "backward-euler", 0.008), "tip_drop", drop, 0.01 * drop);
  ASSERT_TRUE(a) << a.error();
  EXPECT_TRUE(a->full.within);
  const AblationRun* bending = without(*a, "bending");
  ASSERT_TRUE(bending && bending->value) << (bending ? bending->status : "no bending term");
  EXPECT_GT(std::abs(*bending->value - *a->full.value), 0.1 * drop);
  EXPECT_FALSE(bending->within);
  EXPECT_FALSE(a->cheapest && a->cheapest->term.find("bending") != std::string::npos);
}

}  // namespace
}  // namespace springcheck
