// The tolerance file's refusals and the gate's verdict on it.
// ctest-label: unit
// ctest-label Gate: physics
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "compare/studies/gate.h"
#include "compare/studies/tolerances.h"
#include "source_root.h"

namespace springcheck {
namespace {

using test::kRoot;

std::string checkJson(const std::string& fields) { return R"({"checks": [{)" + fields + "}]}"; }
const std::string kGoodCheck =
    R"("scene": "scenes/matched/chain_hanging.json", "engines": ["mysim", "bullet-deformable"],
       "metric": "drape_max", "bound": 1e-4, "why": "test")";

TEST(Tolerances, MalformedFilesAreRefusedNamingTheCheckAndField) {
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {checkJson(R"("engines": ["mysim"], "metric": "sag_lowest", "bound": 1, "why": "w")"),
       "checks[0].scene: missing"},
      {checkJson(R"("scene": "scenes/none.json", "engines": ["mysim"], "metric": "sag_lowest",
                    "bound": 1, "why": "w")"),
       "checks[0].scene: unknown scene"},
      {checkJson(R"("scene": "scenes/matched/chain_hanging.json", "engines": ["havok"],
                    "metric": "sag_lowest", "bound": 1, "why": "w")"),
       "checks[0].engines: unknown engine 'havok'"},
      {checkJson(R"("scene": "scenes/matched/chain_hanging.json", "engines": ["mysim"],
                    "metric": "wobble", "bound": 1, "why": "w")"),
       "checks[0].metric: unknown metric 'wobble'"},
      {checkJson(R"("scene": "scenes/matched/chain_hanging.json", "engines": ["mysim"],
                    "metric": "drape_max", "bound": 1, "why": "w")"),
       "checks[0].engines: metric 'drape_max' takes two engines"},
      {checkJson(R"("scene": "scenes/matched/chain_hanging.json", "engines": ["mysim"],
                    "metric": "sag_lowest", "bound": -1, "why": "w")"),
       "checks[0].bound: expected a finite number >= 0"},
      {checkJson(R"("scene": "scenes/matched/chain_hanging.json", "engines": ["mysim"],
                    "metric": "sag_lowest", "bound": 1, "why": "")"),
       "checks[0].why: expected the reason"},
      {checkJson(kGoodCheck + R"(, "tolerance": 3)"), "checks[0].tolerance: unknown field"},
      {R"({"checks": []})", "checks: expected a non-empty list"},
  };
  EngineRegistry registry;
  for (const Case& c : cases) {
    auto parsed = parseTolerances(c.text, "tol.json", kRoot, registry);
    ASSERT_FALSE(parsed) << c.text;
    EXPECT_EQ(parsed.error().rfind("tol.json: ", 0), 0u) << parsed.error();
    EXPECT_NE(parsed.error().find(c.expected), std::string::npos) << parsed.error();
  }
  EXPECT_TRUE(parseTolerances(checkJson(kGoodCheck), "tol.json", kRoot, registry));
}

TEST(Gate, FailsWhenABoundIsTightenedBelowTheMeasuredValue) {
  EngineRegistry registry;
  auto tolerances = parseTolerances(checkJson(kGoodCheck), "tol.json", kRoot, registry);
  ASSERT_TRUE(tolerances) << tolerances.error();
  const GateReport loose = runGate(registry, *tolerances).value();
  ASSERT_TRUE(loose.results[0].measured);
  EXPECT_TRUE(loose.passed());
  const double measured = *loose.results[0].measured;
  EXPECT_GT(measured, 0.0);
  tolerances->checks[0].bound = 0.5 * measured;
  const GateReport tight = runGate(registry, *tolerances).value();
  EXPECT_FALSE(tight.passed());
  EXPECT_DOUBLE_EQ(*tight.results[0].measured, measured);  // same input, same output
}

TEST(Gate, AnEngineThatRefusesTheSceneFailsItsCheck) {
  EngineRegistry registry;
  auto tolerances =
      parseTolerances(checkJson(R"("scene": "scenes/seed/cloth.json", "engines": ["bullet-classic"],
                   "metric": "sag_lowest", "bound": 10, "why": "w")"),
                      "tol.json", kRoot, registry);
  ASSERT_TRUE(tolerances) << tolerances.error();
  const GateReport report = runGate(registry, *tolerances).value();
  EXPECT_FALSE(report.passed());
  EXPECT_NE(report.results[0].problem.find("refused"), std::string::npos);
}

}  // namespace
}  // namespace springcheck
