// gate --ablate (compare/studies/gate_ablation.h): a term no gated check needs is found, unless
// the scene declares it; a term a check needs is not offered.
// ctest-label: physics
// releaseonly: the cantilever's gate ablation is 12 s under the sanitizers; ablateGate runs there
// in the suite GateAblation (the cable over the ground).
// ctest-label GateAblationOfTheCantilever: physics,releaseonly
#include "compare/studies/gate_ablation.h"
#include "per_test_file.h"
#include "source_root.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

namespace springcheck {
namespace {

using test::kRoot;

const GateTermEffect* effectOf(const std::vector<GateTermEffect>& effects,
                               const std::string& term) {
  for (const GateTermEffect& e : effects) {
    if (e.term == term) return &e;
  }
  return nullptr;
}

// The shipped cable with a ground plane 10 m below it, which it never reaches, held to 1 % of
// the continuous catenary at 10 links; `needs` as given (null: none).
std::vector<GateTermEffect> gateEffectsOverGround(const nlohmann::json& needs) {
  std::ifstream in(kRoot + "/scenes/material/cable_catenary.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["colliders"] = {{{"type", "plane"}, {"point", {0, -10, 0}}, {"normal", {0, 1, 0}}}};
  if (!needs.is_null()) scene["needs"] = needs;
  const std::string path = test_support::perTestJsonPath("gated_cable_over_ground");
  std::ofstream(path) << scene.dump();
  const std::string check = R"({"checks": [{"scene": ")" + path + R"(", "resolution": 10,
      "dt": 0.016, "engines": ["mysim:backward-euler"], "metric": "sag_lowest",
      "physical_error": "relative", "bound": 0.01, "why": "test"}]})";
  EngineRegistry registry;
  auto tolerances = parseTolerances(check, "tol.json", kRoot, registry);
  EXPECT_TRUE(tolerances) << tolerances.error();
  const GateReport report = runGate(registry, *tolerances).value();
  EXPECT_TRUE(report.passed());
  return ablateGate(registry, report).value();
}

TEST(GateAblation, AColliderNoCheckReachesIsOfferedForDropping) {
  const auto effects = gateEffectsOverGround(nullptr);
  const GateTermEffect* ground = effectOf(effects, "colliders");
  ASSERT_TRUE(ground);
  ASSERT_TRUE(ground->ran) << ground->problem;
  EXPECT_TRUE(ground->all_within);
  EXPECT_EQ(ground->largest_share.value_or(-1.0), 0.0);  // the same bits without it
  EXPECT_TRUE(ground->droppable());
  EXPECT_FALSE(effectOf(effects, "bending"));  // a cable carries no bending
}

TEST(GateAblation, ATermTheSceneDeclaresIsNotOffered) {
  const auto effects = gateEffectsOverGround(nlohmann::json::array({"colliders"}));
  const GateTermEffect* ground = effectOf(effects, "colliders");
  ASSERT_TRUE(ground);
  EXPECT_TRUE(ground->all_within);
  EXPECT_TRUE(ground->declared);
  EXPECT_FALSE(ground->droppable());
}

// The 4-cell cantilever held to 5 % of the heavy elastica: without bending the strip hangs from
// its clamp, the tip drops far beyond that, so bending is needed.
TEST(GateAblationOfTheCantilever, BendingIsNeeded) {
  EngineRegistry registry;
  auto tolerances = parseTolerances(
      R"({"checks": [{"scene": "scenes/material/cantilever_strip.json", "resolution": 4,
          "dt": 0.016, "engines": ["mysim:backward-euler"], "metric": "tip_drop",
          "physical_error": "relative", "bound": 0.05, "why": "test"}]})",
      "tol.json", kRoot, registry);
  ASSERT_TRUE(tolerances) << tolerances.error();
  const GateReport report = runGate(registry, *tolerances).value();
  ASSERT_TRUE(report.passed()) << report.results[0].problem;
  const auto effects = ablateGate(registry, report).value();
  const GateTermEffect* bending = effectOf(effects, "bending");
  ASSERT_TRUE(bending);
  ASSERT_TRUE(bending->ran) << bending->problem;
  EXPECT_FALSE(bending->all_within);
  EXPECT_FALSE(bending->droppable());
  EXPECT_GT(bending->largest_share.value_or(0.0), 1.0);
}

}  // namespace
}  // namespace springcheck
