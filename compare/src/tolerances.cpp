#include "compare/tolerances.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include <algorithm>
#include "compare/run_metrics.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::expected<ToleranceCheck, std::string> readCheck(const json& j, const std::string& where,
                                                     const fs::path& root,
                                                     const EngineRegistry& registry) {
  auto bad = [&](const std::string& field, const std::string& why) {
    return std::unexpected(where + "." + field + ": " + why);
  };
  if (!j.is_object()) return std::unexpected(where + ": expected an object");
  static const std::set<std::string> known = {"scene", "engines", "metric", "bound", "why"};
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!known.count(it.key())) return bad(it.key(), "unknown field");
  }
  for (const std::string& field : known) {
    if (!j.contains(field)) return bad(field, "missing (required)");
  }
  ToleranceCheck c;
  if (!j["scene"].is_string()) return bad("scene", "expected a path string");
  c.scene = (root / j["scene"].get<std::string>()).lexically_normal().string();
  if (!fs::exists(c.scene)) return bad("scene", "unknown scene: no file " + c.scene);
  if (auto scene = registry.loadScene(c.scene); !scene) return bad("scene", scene.error());

  if (!j["engines"].is_array() || j["engines"].empty() || j["engines"].size() > 2) {
    return bad("engines", "expected a list of one or two engine names");
  }
  for (const json& e : j["engines"]) {
    if (!e.is_string()) return bad("engines", "expected engine names (strings)");
    if (auto known_engine = registry.check(e.get<std::string>()); !known_engine) {
      return bad("engines", known_engine.error());
    }
    c.engines.push_back(e.get<std::string>());
  }
  if (!j["metric"].is_string()) return bad("metric", "expected a metric name");
  c.metric = j["metric"].get<std::string>();
  const MetricInfo* info = findMetric(c.metric);
  if (!info) {
    std::string names;
    for (const MetricInfo& m : metricCatalog()) names += (names.empty() ? "" : ", ") + m.name;
    return bad("metric", "unknown metric '" + c.metric + "'; expected one of " + names);
  }
  if (c.engines.size() != (info->pair ? 2u : 1u)) {
    return bad("engines",
               "metric '" + c.metric + "' takes " + (info->pair ? "two engines" : "one engine"));
  }
  if (!j["bound"].is_number() || !std::isfinite(j["bound"].get<double>()) ||
      j["bound"].get<double>() < 0) {
    return bad("bound", "expected a finite number >= 0");
  }
  c.bound = j["bound"].get<double>();
  if (!j["why"].is_string() || j["why"].get<std::string>().empty()) {
    return bad("why", "expected the reason for this bound (a non-empty string)");
  }
  c.why = j["why"].get<std::string>();
  return c;
}

}  // namespace

std::expected<Tolerances, std::string> parseTolerances(const std::string& text,
                                                       const std::string& source,
                                                       const std::string& base_dir,
                                                       EngineRegistry& registry) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    return std::unexpected(source + ": not valid JSON: " + e.what());
  }
  if (!root.is_object()) return std::unexpected(source + ": expected an object");
  for (auto it = root.begin(); it != root.end(); ++it) {
    if (it.key() != "scene_root" && it.key() != "checks" && it.key() != "engines_file" &&
        it.key() != "$comment") {
      return std::unexpected(source + ": " + it.key() + ": unknown field");
    }
  }
  fs::path scene_root = base_dir;
  if (root.contains("scene_root")) {
    if (!root["scene_root"].is_string())
      return std::unexpected(source + ": scene_root: expected a path");
    scene_root /= root["scene_root"].get<std::string>();
  }
  if (!root.contains("checks") || !root["checks"].is_array() || root["checks"].empty()) {
    return std::unexpected(source + ": checks: expected a non-empty list of checks");
  }
  Tolerances t{source, {}, ""};
  if (root.contains("engines_file")) {
    if (!root["engines_file"].is_string()) {
      return std::unexpected(source + ": engines_file: expected a path (relative to this file)");
    }
    t.engines_file =
        (fs::path(base_dir) / root["engines_file"].get<std::string>()).lexically_normal().string();
    const auto& read = registry.enginesFiles();
    if (std::find(read.begin(), read.end(), t.engines_file) == read.end()) {
      if (auto added = registry.addEnginesFile(t.engines_file); !added) {
        return std::unexpected(source + ": engines_file: " + added.error());
      }
    }
  }
  for (std::size_t k = 0; k < root["checks"].size(); ++k) {
    auto check =
        readCheck(root["checks"][k], source + ": checks[" + std::to_string(k) + "]", scene_root,
                  registry);
    if (!check) return std::unexpected(check.error());
    t.checks.push_back(std::move(*check));
  }
  return t;
}

std::expected<Tolerances, std::string> loadTolerances(const std::string& path,
                                                      EngineRegistry& registry) {
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot open the tolerances file");
  std::stringstream text;
  text << in.rdbuf();
  return parseTolerances(text.str(), path, fs::path(path).parent_path().string(), registry);
}

}  // namespace springcheck
