#include "compare/io/report_manifest.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

#include "compare/io/csv.h"
#include "compare/io/invocation.h"
#include "compare/io/report_headlines.h"
#include "report_tables.h"

namespace springcheck {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The engines the main job compares on its energy scenes (scripts/run-suite.sh): every engine,
// mysim once per integrator (EngineRegistry::expand).
constexpr const char* kEnergyEngines = "all";

std::vector<fs::path> filesIn(const fs::path& dir, const std::string& prefix,
                              const std::string& extension) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && entry.path().extension() == extension &&
        name.starts_with(prefix)) {
      files.push_back(entry.path());
    }
  }
  std::ranges::sort(files);
  return files;
}

std::string machine() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);) {
    if (line.starts_with("model name")) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  return std::string(host) + ", " + cpu + ", " +
         std::to_string(std::thread::hardware_concurrency()) + " cores";
}

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

// The first data row's value of `column` in a CSV table ("" when absent): enough to tell a
// self-consistency sweep from one against a shared reference.
std::string firstValue(const fs::path& table, const std::string& column) {
  std::error_code ec;
  if (!fs::is_regular_file(table, ec)) return "";  // a FIFO would block
  std::ifstream in(table);
  std::string header, row;
  if (!std::getline(in, header) || !std::getline(in, row)) return "";
  const auto names = parseCsvLine(header), values = parseCsvLine(row);
  if (!names || !values) return "";
  for (std::size_t i = 0; i < names->size() && i < values->size(); ++i) {
    if ((*names)[i] == column) return (*values)[i];
  }
  return "";
}

// A sweep's table for the pages, with the window its errors are over: the simulated time of its
// longest finished case (steps x dt), which the pages state (an error "max over frames" of a 2 s
// run says nothing of the 12 s one).
json sweepEntry(const fs::path& table, bool self_reference) {
  double window = 0.0;
  for (const report_tables::Row& row : report_tables::readTable(table.string())) {
    auto cell = [&](const char* name) {
      const auto it = row.find(name);
      return it == row.end() ? std::nullopt : report_tables::number(it->second);
    };
    const auto dt = cell("dt"), steps = cell("steps");
    if (dt && steps && row.count("status") && row.at("status") == "ok") {
      window = std::max(window, *dt * *steps);
    }
  }
  return {{"name", table.stem().string()}, {"path", table.string()},
          {"self_reference", self_reference}, {"command", invocationBeside(table.string())},
          {"window", window > 0.0 ? json(window) : json()}};
}

// Every folder under `results` holding a comparison.json (suite/SCENE, energy/SCENE,
// compare/SCENE, ...), with its group (the folder above it).
std::expected<json, std::string> comparisons(const fs::path& results) {
  std::vector<fs::path> found;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(results, error);
       !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (it.depth() > 3) it.disable_recursion_pending();
    if (it->path().filename() == "comparison.json") found.push_back(it->path().parent_path());
  }
  std::ranges::sort(found);
  json list = json::array();
  for (const fs::path& dir : found) {
    std::error_code ec;
    if (!fs::is_regular_file(dir / "comparison.json", ec)) {  // a FIFO would block the reader
      return std::unexpected((dir / "comparison.json").string() + ": not a regular file");
    }
    std::ifstream in(dir / "comparison.json");
    json c = json::parse(in, nullptr, false);
    if (c.is_discarded() || !c.contains("scene") || !c.contains("engines")) {
      return std::unexpected((dir / "comparison.json").string() +
                             ": not a comparison written by springcheck compare or suite");
    }
    json entry = {{"group", fs::relative(dir.parent_path(), results).string()},
                  {"scene", c["scene"]},
                  {"scene_file", c.value("scene_file", "")},
                  {"command", c.value("command", json())},
                  {"folder", dir.string()},
                  {"model", c.value("model", json::object())},
                  {"energy_reference", c.value("energy_reference", json())},
                  {"refused", c.value("refused", json::array())},
                  {"failed", c.value("failed", json::array())},
                  {"engines", json::array()}};
    for (const char* table : {"series", "engine_metrics", "pair_metrics", "node_distance"}) {
      const fs::path path = dir / (std::string(table) + ".csv");
      entry[table] = fs::exists(path) ? json(path.string()) : json();
    }
    for (const json& e : c["engines"]) {
      const fs::path run = dir / e.value("folder", e.value("engine", ""));
      json engine = {{"name", e.value("engine", "")},
                     {"integrator", e.value("integrator", "")},
                     {"status", e.value("status", "")},
                     {"folder", run.string()}};
      for (const char* file : {"final_state.csv", "final.obj", "energy.csv"}) {
        engine[std::string(file).substr(0, std::string(file).find('.'))] =
            fs::exists(run / file) ? json((run / file).string()) : json();
      }
      entry["engines"].push_back(engine);
    }
    list.push_back(entry);
  }
  return list;
}

// The trade studies (springcheck trade) under results/trade: each folder's answer and table.
json tradeStudies(const fs::path& results) {
  json studies = json::array();
  std::error_code ec;
  std::vector<fs::path> answers;
  for (const auto& entry : fs::directory_iterator(results / "trade", ec)) {
    if (entry.is_directory() && fs::exists(entry.path() / "trade.json")) {
      answers.push_back(entry.path() / "trade.json");
    }
  }
  std::sort(answers.begin(), answers.end());
  for (const fs::path& a : answers) {
    const fs::path table = a.parent_path() / "trade.csv";
    studies.push_back({{"answer", a.string()},
                       {"table", table.string()},
                       {"command", invocationBeside(table.string())}});
  }
  return studies;
}

// Names an input the report lacks, the command that makes it and the pages that need it.
class MissingInputs {
 public:
  explicit MissingInputs(json& list) : list_(list) {}
  void operator()(const std::string& input, const std::string& command,
                  const std::string& pages) const {
    list_.push_back({{"input", input}, {"command", command}, {"pages", pages}});
  }

 private:
  json& list_;
};

// The sweeps' tables, their recommendations and every recommendation's bound.
void addSweeps(json& m, const fs::path& results, const std::string& d,
               const MissingInputs& missing) {
  m["sweeps"] = json::array();
  m["recommendations"] = json::array();
  for (const fs::path& table : filesIn(results / "sweep", "", ".csv")) {
    const std::string name = table.stem().string();
    const bool self = firstValue(table, "reference").starts_with("self");
    m["sweeps"].push_back(sweepEntry(table, self));
    const fs::path rec = results / "recommend" / (name + ".json");
    if (fs::exists(rec)) {
      m["recommendations"].push_back({{"sweep", name}, {"path", rec.string()}});
    } else if (!self) {
      missing(
          rec.string(),
          "springcheck recommend " + table.string() + " --max-error 1e-3 --json " + rec.string(),
          "the dashboard's recommendation");
    }
  }
  // Every recommendation written, with its bound (a sweep recommended at 1 mm and at 1 cm has
  // two): what the solver-family page compares.
  m["recommendation_bounds"] = json::array();
  for (const fs::path& rec : filesIn(results / "recommend", "", ".json")) {
    std::ifstream in(rec);
    const json j = json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("table") || !j.contains("max_error")) continue;
    m["recommendation_bounds"].push_back(
        {{"sweep", fs::path(j["table"].get<std::string>()).stem().string()},
         {"max_error", j["max_error"]},
         {"path", rec.string()}});
  }
  if (m["sweeps"].empty()) {
    for (const char* spec :
         {"chain_convergence", "cloth_speed_accuracy", "chain_self_consistency"}) {
      const std::string table = results.string() + "/sweep/" + spec + ".csv";
      missing(table, "springcheck sweep " + d + "/compare/sweeps/" + spec + ".json --out " + table,
              "speed and accuracy, convergence, the recommendation");
    }
  }
}

// The oscillator's stability table, the extremes and every scene's stability map.
void addStability(json& m, const fs::path& results, const std::string& d,
                  const MissingInputs& missing) {
  const fs::path stability = results / "stability";
  for (const char* table : {"stability", "extremes"}) {
    const fs::path path = stability / (std::string(table) + ".csv");
    m["stability"][table] = fs::exists(path) ? json(path.string()) : json();
    m["stability"][std::string(table) + "_command"] = invocationBeside(path.string());
  }
  if (m["stability"]["stability"].is_null() || m["stability"]["extremes"].is_null()) {
    missing((stability / "stability.csv").string(),
            "springcheck stability --extremes --out " + stability.string(),
            "stability of the integrators on the oscillator, the extremes");
  }
  m["stability"]["scenes"] = json::array();
  for (const fs::path& table : filesIn(stability, "stability_", ".csv")) {
    m["stability"]["scenes"].push_back(
        {{"scene", table.stem().string().substr(std::string("stability_").size())},
         {"path", table.string()},
         {"command", invocationBeside(table.string())}});
  }
  if (m["stability"]["scenes"].empty()) {
    missing((stability / "stability_chain_swing.csv").string(),
            "springcheck stability --scene " + d + "/scenes/matched/chain_swing.json --out " +
                stability.string(),
            "every engine's stability map");
  }
}

// The comparisons, and which of the main job's groups (suite, energy) are missing.
std::expected<void, std::string> addComparisons(json& m, const fs::path& results,
                                                const std::string& d,
                                                const MissingInputs& missing) {
  auto found = comparisons(results);
  if (!found) return std::unexpected(found.error());
  m["comparisons"] = std::move(*found);
  auto any_in = [&](const std::string& group) {
    return std::ranges::any_of(m["comparisons"],
                               [&](const json& c) { return c["group"] == group; });
  };
  const std::string r = results.string();
  if (!any_in("suite")) {
    missing(r + "/suite", "springcheck suite " + d + "/scenes --out " + r + "/suite",
            "drapes, sag and penetration, the largest disagreement");
  }
  if (!any_in("energy")) {
    for (const char* scene : {"chain_swing", "chain_hanging"}) {
      const std::string folder = r + "/energy/" + scene;
      missing(folder,
              "springcheck compare " + d + "/scenes/matched/" + scene + ".json --engines " +
                  kEnergyEngines + " --out " + folder,
              "energy of every integrator and engine");
    }
  }
  return {};
}

// Mesh refinement (springcheck refine): the table, its estimates and the command that made them.
void addRefinement(json& m, const fs::path& results, const std::string& d,
                   const MissingInputs& missing) {
  const fs::path refine = results / "refine" / "refine.csv";
  if (fs::exists(refine) && fs::exists(results / "refine" / "refine_estimates.csv")) {
    m["refine"] = {{"table", refine.string()},
                   {"estimates", (results / "refine" / "refine_estimates.csv").string()},
                   {"command", invocationBeside(refine.string())}};
    return;
  }
  m["refine"] = nullptr;
  const std::string scenes = d + "/scenes/material/";
  missing(refine.string(),
          "springcheck refine " + scenes + "cantilever_strip.json " + scenes +
              "cantilever_strip_flex.json " + scenes + "cusick_drape.json " + scenes +
              "cable_catenary.json --resolutions 4,8,16 --engines mysim,bullet-implicit --out " +
              results.string() + "/refine",
          "convergence as the mesh is refined: the cantilever against the elastica, flex "
          "springs, the drape test, the cable against the catenary");
}

// The benchmarks (not part of the main job: they take minutes) and the main job's stage times
// (scripts/run-suite.sh writes them: the last page's table).
void addBenchAndTimings(json& m, const fs::path& results, const MissingInputs& missing) {
  const fs::path bench = results / "bench" / "bench.json";
  m["bench"] = fs::exists(bench) ? json(bench.string()) : json();
  if (m["bench"].is_null()) {
    missing(bench.string(),
            "SPRINGCHECK_OUT=" + results.string() + " scripts/run-bench.sh (from a checkout)",
            "performance: time per step and force evaluations of each engine");
  }
  const fs::path timings = results / "timings.json";
  std::error_code regular;
  m["timings"] = fs::is_regular_file(timings, regular) ? json(timings.string()) : json();
}

}  // namespace

std::expected<json, std::string> reportManifest(const std::string& results_dir,
                                                const ReportStamp& stamp,
                                                const std::vector<ReportSeries>& series) {
  const fs::path results(results_dir);
  const std::string& d = stamp.data_dir;
  json m = {{"stamp",
             {{"version", stamp.version},
              {"commit", stamp.commit},
              {"command", stamp.command},
              {"date", utcNow()},
              {"machine", machine()}}},
            {"results", results_dir},
            {"series", json::array()},
            {"missing", json::array()}};
  for (const ReportSeries& s : series) m["series"].push_back({{"key", s.key}, {"kind", s.kind}});
  const MissingInputs missing(m["missing"]);

  const fs::path gate = results / "gate.json";
  m["gate"] = fs::exists(gate) ? json(gate.string()) : json();
  if (!fs::exists(gate)) {
    missing(gate.string(), "springcheck gate --json " + gate.string(),
            "the dashboard's gate table");
  }
  addSweeps(m, results, d, missing);
  addStability(m, results, d, missing);
  if (auto added = addComparisons(m, results, d, missing); !added) {
    return std::unexpected(added.error());
  }
  addRefinement(m, results, d, missing);
  m["physical_trade"] = tradeStudies(results);
  m["headlines"] = reportHeadlines(m["comparisons"], m["stability"]["scenes"]);
  addBenchAndTimings(m, results, missing);
  return m;
}

}  // namespace springcheck
