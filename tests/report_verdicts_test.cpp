// The report's first page holds each engine to its closed forms (compare/io/src/engine_verdicts.h):
// within 1 % of the exact value (1 mm where it is 0) it is trusted for a scene, a run that did
// not finish misses it, and the stability headline's worst cell is the worst over every mass
// ratio mapped. A tolerance check may name the known bias its bound allows.
// ctest-label: unit
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "compare/engines/engine_registry.h"
#include "compare/io/report_headlines.h"
#include "compare/studies/gate.h"
#include "compare/studies/gate_report_formats.h"
#include "compare/studies/tolerances.h"
#include "source_root.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json engine(const std::string& name, double error, double exact, const std::string& unit) {
  return {{"engine", name}, {"status", "ok"}, {"closed_form_error", error},
          {"closed_form", {{"quantity", "q"}, {"exact", exact}, {"unit", unit}}}};
}

json blownUp(const std::string& name, double when) {
  return {{"engine", name}, {"status", "blowup"}, {"blowup_time", when}};
}

struct Folder {
  fs::path dir = fs::temp_directory_path() / ("springcheck_verdicts_" + std::to_string(::getpid()));
  json comparisons = json::array();
  void add(const std::string& scene, const json& engines) {
    fs::create_directories(dir / scene);
    std::ofstream(dir / scene / "comparison.json")
        << json{{"duration", 2.0}, {"model", {{"kind", "chain"}, {"damped", true}}},
                {"engines", engines}, {"pairs", json::array()}};
    comparisons.push_back({{"group", "suite"}, {"scene", scene}, {"folder", (dir / scene).string()}});
  }
  ~Folder() { fs::remove_all(dir); }
};

const json* verdictOf(const json& headlines, const std::string& name) {
  for (const json& v : headlines["verdicts"]) {
    if (v["engine"] == name) return &v;
  }
  return nullptr;
}

TEST(EngineVerdicts, AClosedFormIsMetWithinOnePercentOfTheExactValueAndABlownUpRunMissesIt) {
  Folder f;
  f.add("circle", {engine("x", 0.005, 1.0, "m"), engine("y", 0.02, 1.0, "m"), blownUp("z", 0.1)});
  f.add("pendulum", {engine("x", 0.008, 2.4, "rel"), engine("y", 0.013, 2.4, "rel")});
  f.add("sticks", {engine("x", 5e-4, 0.0, "m"), engine("y", 2e-3, 0.0, "m")});
  const json h = reportHeadlines(f.comparisons, json::array());
  const json& x = *verdictOf(h, "x");
  EXPECT_EQ(x["closed_forms"]["trusted"], 3);  // 0.5 %, 0.8 % (already relative), 0.5 mm at rest
  EXPECT_EQ(x["closed_forms"]["scenes"], 3);
  const json& y = *verdictOf(h, "y");
  EXPECT_EQ(y["closed_forms"]["trusted"], 0);
  ASSERT_EQ(y["closed_forms"]["misses"].size(), 3u);  // worst relative first, the one at rest last
  EXPECT_EQ(y["closed_forms"]["misses"][0]["scene"], "circle");
  EXPECT_DOUBLE_EQ(y["closed_forms"]["misses"][0]["relative"].get<double>(), 0.02);
  EXPECT_EQ(y["closed_forms"]["misses"][1]["scene"], "pendulum");
  EXPECT_EQ(y["closed_forms"]["misses"][2]["scene"], "sticks");
  EXPECT_FALSE(y["closed_forms"]["misses"][2].contains("relative"));
  EXPECT_EQ(y["closed_form"]["scene"], "circle");  // its key number: the worst measured
  const json& z = *verdictOf(h, "z");
  EXPECT_EQ(z["closed_forms"]["scenes"], 1);
  EXPECT_EQ(z["closed_forms"]["trusted"], 0);
  EXPECT_EQ(z["closed_forms"]["misses"][0]["status"], "blowup");
  EXPECT_DOUBLE_EQ(z["closed_forms"]["misses"][0]["window"].get<double>(), 2.0);
}

TEST(EngineVerdicts, TheStabilityHeadlineTakesTheWorstCellOverEveryMassRatio) {
  const fs::path table =
      fs::temp_directory_path() / ("springcheck_stability_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(table)
      << "system,engine,classic_iterations,stiffness_scale,mass_ratio,w_max,h_stable,h_unstable,"
         "status,unstable_check,theory_h,ratio,h_w_max\n"
         "c,e,,1,1,100,0.0192,0.0193,bracketed,energy-rise,0.02,0.96,1.92\n"
         "c,e,,1,10000,1000,0.00118,0.00119,bracketed,energy-rise,0.002,0.59,1.18\n"
         "c,s,,1,1,100,0.3,,stable-at-max,,,,30\n";
  const json scenes = {{{"scene", "c"}, {"path", table.string()}}};
  const json h = reportHeadlines(json::array(), scenes);
  fs::remove(table);
  const json& map = h["stability"][0];
  EXPECT_EQ(map["mass_ratios"], json({1.0, 10000.0}));
  EXPECT_DOUBLE_EQ(map["engines"][0]["ratio_worst"].get<double>(), 0.59);  // not 0.96 (ratio 1 only)
  EXPECT_DOUBLE_EQ(map["engines"][0]["ratio_best"].get<double>(), 0.96);
  EXPECT_EQ(map["engines"][1]["stable_at_max"], 1);
}

const std::string kCheck = R"({"checks": [{"scene": "scenes/matched/chain_hanging.json",
    "engines": ["bullet-classic"], "metric": "closed_form_error", "bound": 0.053, "why": "w")";

TEST(ToleranceKnownBias, IsReadAndWrittenToTheGateJsonAndAnEmptyOneIsRefused) {
  EngineRegistry registry;
  auto empty = parseTolerances(kCheck + R"(, "known_bias": ""}]})", "tol.json", test::kRoot, registry);
  ASSERT_FALSE(empty);
  EXPECT_NE(empty.error().find("tol.json: checks[0].known_bias: expected the bias"), std::string::npos)
      << empty.error();
  auto given = parseTolerances(kCheck + R"(, "known_bias": "links 12 % stiffer"}]})", "tol.json",
                               test::kRoot, registry);
  ASSERT_TRUE(given) << given.error();
  EXPECT_EQ(given->checks[0].known_bias, "links 12 % stiffer");
  GateReport report;
  report.results.push_back({given->checks[0]});
  std::ostringstream out;
  writeGateJson(out, report, "tol.json");
  EXPECT_EQ(json::parse(out.str())["checks"][0]["known_bias"], "links 12 % stiffer");
}

}  // namespace
}  // namespace springcheck
