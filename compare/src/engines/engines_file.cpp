// Engines files: the user's own simulators, declared as commands.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "compare/external_engine.h"

namespace springcheck {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const std::set<std::string>& placeholders() {
  static const std::set<std::string> names = {"model", "out",      "dir",        "python",
                                              "dt",    "duration", "integrator", "scene"};
  return names;
}

std::expected<ExternalEngineSpec, std::string> readEntry(const json& j, const std::string& where) {
  auto bad = [&](const std::string& field, const std::string& why) {
    return std::unexpected(where + "." + field + ": " + why);
  };
  if (!j.is_object()) return std::unexpected(where + ": expected an object");
  static const std::set<std::string> known = {"$comment", "name", "description", "command",
                                              "time_limit"};
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!known.count(it.key())) {
      return bad(it.key(), "unknown field (expected name, description, command, time_limit)");
    }
  }
  ExternalEngineSpec spec;
  if (!j.contains("name") || !j["name"].is_string()) {
    return bad("name", "expected the engine's name (a string)");
  }
  spec.name = j["name"].get<std::string>();
  if (!std::regex_match(spec.name, std::regex("[a-z0-9][a-z0-9._-]{0,63}"))) {
    return bad("name", "'" + spec.name +
                           "': expected lower-case letters, digits, '.', '_' or '-' (at most "
                           "64, no ':'), since it names folders and columns");
  }
  if (j.contains("description")) {
    if (!j["description"].is_string()) return bad("description", "expected a string");
    spec.description = j["description"].get<std::string>();
  }
  if (!j.contains("command") || !j["command"].is_array() || j["command"].empty()) {
    return bad("command", "expected the program and its arguments as a non-empty list of strings");
  }
  for (std::size_t k = 0; k < j["command"].size(); ++k) {
    const json& arg = j["command"][k];
    const std::string field = "command[" + std::to_string(k) + "]";
    if (!arg.is_string()) return bad(field, "expected a string");
    const std::string text = arg.get<std::string>();
    static const std::regex placeholder("\\{([^}]*)\\}");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), placeholder);
         it != std::sregex_iterator(); ++it) {
      if (!placeholders().count((*it)[1])) {
        return bad(field, "unknown placeholder " + it->str() +
                              " (known: {model} {out} {dir} {python} {dt} {duration} "
                              "{integrator} {scene})");
      }
    }
    spec.command.push_back(text);
  }
  if (j.contains("time_limit")) {
    const json& t = j["time_limit"];
    if (!t.is_number() || !std::isfinite(t.get<double>()) || !(t.get<double>() > 0)) {
      return bad("time_limit", "expected a number of seconds > 0");
    }
    spec.time_limit = t.get<double>();
  }
  return spec;
}

}  // namespace

std::expected<std::vector<ExternalEngineSpec>, std::string> loadEnginesFile(
    const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    return std::unexpected(path + ": " +
                           (fs::exists(path, ec) ? "not a regular file" : "no such file") +
                           " (expected an engines file, docs/external-engines.md)");
  }
  std::ifstream in(path);
  if (!in) return std::unexpected(path + ": cannot open the engines file");
  json j;
  try {
    j = json::parse(in, nullptr, true, false);
  } catch (const json::exception& e) {
    return std::unexpected(path + ": not valid JSON: " + e.what());
  }
  if (!j.is_object()) return std::unexpected(path + ": expected an object with \"engines\"");
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() != "engines" && it.key() != "$comment") {
      return std::unexpected(path + ": " + it.key() + ": unknown field (expected engines)");
    }
  }
  if (!j.contains("engines") || !j["engines"].is_array() || j["engines"].empty()) {
    return std::unexpected(path + ": engines: expected a non-empty list of engines");
  }
  std::vector<ExternalEngineSpec> specs;
  std::set<std::string> names;
  const std::string dir = fs::absolute(path).parent_path().lexically_normal().string();
  for (std::size_t k = 0; k < j["engines"].size(); ++k) {
    const std::string where = path + ": engines[" + std::to_string(k) + "]";
    auto spec = readEntry(j["engines"][k], where);
    if (!spec) return std::unexpected(spec.error());
    if (!names.insert(spec->name).second) {
      return std::unexpected(where + ".name: '" + spec->name + "' appears twice");
    }
    spec->source = path;
    spec->dir = dir;
    specs.push_back(std::move(*spec));
  }
  return specs;
}

}  // namespace springcheck
