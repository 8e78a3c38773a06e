// Gating the physical errors a trade promises (docs/compare.md): a check on a material scene's
// variant (resolution, step) holds the metric against its closed form, independently computed.
// ctest-label: physics
#include <gtest/gtest.h>

#include <cmath>

#include "compare/metrics/elastic_catenary.h"
#include "compare/studies/gate.h"
#include "compare/studies/tolerances.h"
#include "source_root.h"

namespace springcheck {
namespace {

using test::kRoot;

std::string cableCheck(int links, const std::string& relative) {
  return R"({"scene": "scenes/material/cable_catenary.json", "resolution": )" +
         std::to_string(links) + R"(, "dt": 0.016, "engines": ["mysim:backward-euler"],
            "metric": "sag_lowest", "physical_error": ")" + relative +
         R"(", "bound": 0.01, "why": "test"})";
}

// The shipped cable (1 m span, 1 m long, 0.05 kg/m, EA 50 N) at 5 and 10 links: each check runs
// its own variant, holds the sag against the continuous elastic catenary, and the finer cable
// is the closer (the discretisation error falls with the links).
TEST(PhysicalGate, EachVariantIsHeldAgainstTheContinuousCatenary) {
  EngineRegistry registry;
  auto tolerances = parseTolerances(R"({"checks": [)" + cableCheck(5, "absolute") + ", " +
                                        cableCheck(10, "absolute") + ", " +
                                        cableCheck(10, "relative") + "]}",
                                    "tol.json", kRoot, registry);
  ASSERT_TRUE(tolerances) << tolerances.error();
  const double sag = levelElasticCatenary(1.0, 1.0, 0.05 * 9.8, 50.0).midspan_sag;
  EXPECT_NEAR(tolerances->checks[0].reference, sag, 1e-12 * sag);
  EXPECT_EQ(tolerances->scenes.size(), 2u);  // two variants, each read once
  const GateReport report = runGate(registry, *tolerances).value();
  ASSERT_EQ(report.results.size(), 3u);
  for (const CheckResult& r : report.results) ASSERT_TRUE(r.measured) << r.problem;
  const double coarse = *report.results[0].measured, fine = *report.results[1].measured;
  EXPECT_GT(fine, 0.0);
  EXPECT_LT(fine, 0.5 * coarse);  // second order in the links: about a quarter
  EXPECT_NEAR(*report.results[2].measured, fine / sag, 1e-12);
  EXPECT_EQ(report.results[2].unit, "rel");
  EXPECT_TRUE(report.results[2].passed);
}

TEST(PhysicalGate, AVariantOrAPhysicalErrorWithoutAClosedFormIsRefusedNamingTheField) {
  struct Case {
    std::string check, expected;
  };
  const std::vector<Case> cases = {
      {R"("scene": "scenes/matched/chain_hanging.json", "resolution": 8, "engines": ["mysim"],
          "metric": "sag_lowest", "bound": 1, "why": "w")",
       "checks[0].resolution: no variant at a resolution"},
      {R"("scene": "scenes/material/cable_catenary.json", "resolution": 0, "engines": ["mysim"],
          "metric": "sag_lowest", "bound": 1, "why": "w")",
       "checks[0].resolution: expected an integer"},
      {R"("scene": "scenes/material/cable_catenary.json", "dt": -1, "engines": ["mysim"],
          "metric": "sag_lowest", "bound": 1, "why": "w")",
       "checks[0].dt: expected a number > 0"},
      {R"("scene": "scenes/material/cable_catenary.json", "engines": ["mysim"],
          "metric": "sag_lowest", "physical_error": "relativ", "bound": 1, "why": "w")",
       "checks[0].physical_error: expected \"absolute\" or \"relative\""},
      {R"("scene": "scenes/matched/chain_hanging.json", "engines": ["mysim"],
          "metric": "sag_lowest", "physical_error": "absolute", "bound": 1, "why": "w")",
       "checks[0].physical_error: the scene has no closed form for 'sag_lowest'"},
      {R"("scene": "scenes/material/cantilever_strip.json", "engines": ["mysim"],
          "metric": "drape_coefficient", "physical_error": "absolute", "bound": 1, "why": "w")",
       "checks[0].physical_error: the scene has no closed form for 'drape_coefficient'"},
  };
  EngineRegistry registry;
  for (const Case& c : cases) {
    auto parsed = parseTolerances(R"({"checks": [{)" + c.check + "}]}", "tol.json", kRoot, registry);
    ASSERT_FALSE(parsed) << c.check;
    EXPECT_EQ(parsed.error().rfind("tol.json: ", 0), 0u) << parsed.error();
    EXPECT_NE(parsed.error().find(c.expected), std::string::npos) << parsed.error();
  }
}

}  // namespace
}  // namespace springcheck
