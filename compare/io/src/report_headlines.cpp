#include "compare/io/report_headlines.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "compare/io/csv.h"

namespace springcheck {
namespace {

using nlohmann::json;
using Row = std::map<std::string, std::string>;

std::vector<Row> readTable(const std::string& path) {
  std::vector<Row> rows;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return rows;  // a FIFO would block
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return rows;
  const auto names = parseCsvLine(line);
  if (!names) return rows;
  while (std::getline(in, line)) {
    const auto values = parseCsvLine(line);
    if (!values || values->size() != names->size()) continue;
    Row row;
    for (std::size_t k = 0; k < names->size(); ++k) row[(*names)[k]] = (*values)[k];
    rows.push_back(std::move(row));
  }
  return rows;
}

std::optional<double> number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

json readJson(const std::string& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return nullptr;
  std::ifstream in(file);
  json j = json::parse(in, nullptr, false);
  return j.is_discarded() ? json() : j;
}

std::optional<double> numberIn(const json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

// A cloth comparison's state at its last frame: settled (every engine's kinetic energy stayed
// below 1e-4 of its peak from some time on, the latest such time, at most 90 % into the run: a
// cloth that got there in the last tenth has not shown it stays), driven (wind or moving pins:
// it never rests), or still moving at the end.
json clothState(const json& comparison) {
  const bool driven = comparison["model"].value("driven", false);
  const double end = comparison.value("duration", 0.0);
  if (driven) return {{"state", "driven"}, {"last_frame", end}};
  double settled = 0.0;
  for (const json& e : comparison["engines"]) {
    const auto t = numberIn(e, "settling_time");
    if (!t || *t > 0.9 * end) return {{"state", "moving"}, {"last_frame", end}};
    settled = std::max(settled, *t);
  }
  return {{"state", "settled"}, {"settled_at", settled}, {"last_frame", end}};
}

// Final-frame distances mean a disagreement of rest shapes only where every engine has settled:
// the largest there (mirror-aware: a fold buckled the other way is not a disagreement), and,
// apart, the largest trajectory difference on cloths still moving or driven at the end.
json clothDisagreements(const json& comparisons) {
  json rest, moving, states = json::object();
  for (const json& c : comparisons) {
    if (c["group"] == "energy") continue;
    const json j = readJson(c["folder"].get<std::string>() + "/comparison.json");
    if (j.is_null() || j["model"].value("kind", "") != "cloth") continue;
    const json state = clothState(j);
    states[c["group"].get<std::string>() + "/" + c["scene"].get<std::string>()] = state;
    // The drape page draws every engine against the first: the headline's pair is one it shows.
    const json first = j["engines"].empty() ? json() : j["engines"][0]["engine"];
    for (const json& p : j["pairs"]) {
      json where = {{"a", p["a"]}, {"b", p["b"]}, {"scene", c["scene"]}, {"group", c["group"]},
                    {"state", state}};
      if (state["state"] == "settled") {
        if (p["a"] != first && p["b"] != first) continue;
        const auto v = numberIn(p, "drape_max_mirror_aware") ? numberIn(p, "drape_max_mirror_aware")
                                                             : numberIn(p, "drape_max");
        if (v && (rest.is_null() || *v > rest["value"].get<double>())) {
          rest = where;
          rest["value"] = *v;
          rest["mirrored"] = numberIn(p, "drape_mirrored").value_or(0.0) == 1.0;
        }
      } else if (const auto v = numberIn(p, "trajectory_rms_max")) {
        if (moving.is_null() || *v > moving["value"].get<double>()) {
          moving = where;
          moving["value"] = *v;
        }
      }
    }
  }
  return {{"rest", rest}, {"moving", moving}, {"states", states}};
}

// The state of any comparison's last frame (chains too): as clothState, for every system.
json lastFrameState(const json& comparison) { return clothState(comparison); }

// One picture ranking the engines by scene: for each suite scene, each engine's error against the
// closed form where the scene has one, else its distance to the scene's first engine (mysim at the
// scene's integrator): the rest shape (mirror-aware) where every engine settled, the trajectory
// otherwise; each scene marked settled, moving or driven.
json ranking(const json& comparisons) {
  json scenes = json::array();
  for (const json& c : comparisons) {
    if (c["group"] != "suite") continue;
    const json j = readJson(c["folder"].get<std::string>() + "/comparison.json");
    if (j.is_null() || j["engines"].empty()) continue;
    const json state = lastFrameState(j);
    json values = json::object();
    std::string measure;
    bool closed = false;
    for (const json& e : j["engines"]) closed |= numberIn(e, "closed_form_error").has_value();
    if (closed) {
      measure = "closed form";
      for (const json& e : j["engines"]) {
        if (const auto v = numberIn(e, "closed_form_error")) values[e["engine"].get<std::string>()] = *v;
      }
    } else {
      const std::string first = j["engines"][0]["engine"];
      const bool rest = state["state"] == "settled";
      measure = rest ? "rest shape vs " + first : "trajectory vs " + first;
      values[first] = 0.0;  // the reference itself
      for (const json& p : j["pairs"]) {
        if (p["a"] != first) continue;
        const auto v = rest ? (numberIn(p, "drape_max_mirror_aware") ? numberIn(p, "drape_max_mirror_aware")
                                                                     : numberIn(p, "drape_max"))
                            : numberIn(p, "trajectory_rms_max");
        if (v) values[p["b"].get<std::string>()] = *v;
      }
    }
    json blown = json::array();
    for (const json& e : j["engines"]) {
      if (e.value("status", "ok") != "ok") blown.push_back(e["engine"]);
    }
    scenes.push_back({{"scene", c["scene"]}, {"state", state}, {"measure", measure},
                      {"values", values}, {"not_ok", blown}});
  }
  return scenes;
}

// One line per engine over the suite: the engine it is closest to on settled cloths, its worst
// energy drift on a scene nothing drives or damps (on a damped one the drift is the damping), its worst momentum drift on a free body, its worst
// closed-form error. Numbers only; the report words them.
json verdicts(const json& comparisons, const json& stability_scenes) {
  std::map<std::string, json> by_engine;
  std::map<std::string, std::map<std::string, std::vector<double>>> closeness;
  std::vector<std::string> order;
  for (const json& c : comparisons) {
    if (c["group"] != "suite") continue;
    const json j = readJson(c["folder"].get<std::string>() + "/comparison.json");
    if (j.is_null()) continue;
    const json state = lastFrameState(j);
    // Energy is a conservation check only where nothing drives or damps the scene.
    const bool conservative = state["state"] != "driven" && !j["model"].value("damped", true);
    for (const json& e : j["engines"]) {
      const std::string name = e["engine"];
      if (!by_engine.count(name)) {
        order.push_back(name);
        by_engine[name] = {{"engine", name}};
      }
      json& v = by_engine[name];
      auto worse = [&](const char* field, std::optional<double> value) {
        if (!value) return;
        if (!v.contains(field) || *value > v[field]["value"].get<double>()) {
          v[field] = {{"value", *value}, {"scene", c["scene"]}};
        }
      };
      if (conservative) worse("energy_drift", numberIn(e, "energy_drift_max"));
      worse("linear_momentum", numberIn(e, "linear_momentum_drift"));
      worse("angular_momentum", numberIn(e, "angular_momentum_drift"));
      worse("closed_form", numberIn(e, "closed_form_error"));
      if (e.value("status", "ok") != "ok") v["not_ok"].push_back(c["scene"]);
    }
    if (state["state"] != "settled" || j["model"].value("kind", "") != "cloth") continue;
    for (const json& p : j["pairs"]) {
      const auto d = numberIn(p, "drape_max_mirror_aware") ? numberIn(p, "drape_max_mirror_aware")
                                                           : numberIn(p, "drape_max");
      if (!d) continue;
      closeness[p["a"]][p["b"]].push_back(*d);
      closeness[p["b"]][p["a"]].push_back(*d);
    }
  }
  // Each engine's step rule on each mapped scene as written (stiffness scale 1, the lowest mass
  // ratio): h < c / w_max with this scene's w_max, and the largest stable step measured.
  std::map<std::string, json> rules;
  for (const json& entry : stability_scenes) {
    const std::vector<Row> rows = readTable(entry["path"]);
    double lowest = INFINITY;
    for (const Row& r : rows) lowest = std::min(lowest, number(r.at("mass_ratio")).value_or(INFINITY));
    for (const Row& r : rows) {
      if (number(r.at("mass_ratio")) != lowest || number(r.at("stiffness_scale")) != 1.0) continue;
      if (!r.at("classic_iterations").empty() && r.at("classic_iterations") != "10") continue;
      json rule = {{"scene", entry["scene"]}, {"status", r.at("status")}};
      for (const char* key : {"w_max", "theory_h", "h_stable"}) {
        if (auto v = number(r.at(key))) rule[key] = *v;
      }
      rules[r.at("engine")].push_back(rule);
    }
  }
  json list = json::array();
  for (const std::string& name : order) {
    json v = by_engine[name];
    if (rules.count(name)) v["step_rules"] = rules[name];
    std::string nearest;
    double best = INFINITY;
    for (const auto& [other, distances] : closeness[name]) {
      const double m = median(distances);
      if (m < best) best = m, nearest = other;
    }
    if (!nearest.empty()) {
      v["closest"] = {{"engine", nearest}, {"median", best},
                      {"scenes", closeness[name][nearest].size()}};
    }
    list.push_back(v);
  }
  return list;
}

// Each free body of the suite: its worst linear and its worst angular drift, each with its own
// engine.
json momentum(const json& comparisons) {
  json list = json::array();
  for (const json& c : comparisons) {
    if (c["group"] != "suite") continue;
    const std::string file = c["folder"].get<std::string>() + "/comparison.json";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) continue;
    std::ifstream in(file);
    const json j = json::parse(in, nullptr, false);
    if (j.is_discarded()) continue;
    json entry = {{"scene", c["scene"]}};
    for (const char* key : {"linear_momentum_drift", "angular_momentum_drift"}) {
      for (const json& e : j["engines"]) {
        if (!e.contains(key) || !e[key].is_number()) continue;
        if (!entry.contains(key) || e[key].get<double>() > entry[key]["value"].get<double>()) {
          entry[key] = {{"engine", e["engine"]}, {"value", e[key]}};
        }
      }
    }
    if (entry.size() > 1) list.push_back(entry);
  }
  return list;
}

// Per scene map: every engine (bullet-classic per pass count) at the lowest mass ratio mapped.
json stability(const json& stability_scenes) {
  json scenes = json::array();
  for (const json& entry : stability_scenes) {
    const std::vector<Row> rows = readTable(entry["path"]);
    double lowest = INFINITY;
    for (const Row& r : rows)
      lowest = std::min(lowest, number(r.at("mass_ratio")).value_or(INFINITY));
    std::map<std::string, std::vector<const Row*>> groups;
    std::vector<std::string> order;
    for (const Row& r : rows) {
      if (number(r.at("mass_ratio")) != lowest) continue;
      const std::string key =
          r.at("engine") +
          (r.at("classic_iterations").empty() ? "" : " (" + r.at("classic_iterations") + ")");
      if (!groups.count(key)) order.push_back(key);
      groups[key].push_back(&r);
    }
    json engines = json::array();
    for (const std::string& key : order) {
      std::vector<double> hw, ratio;
      int refused = 0, stable_at_max = 0;
      for (const Row* r : groups[key]) {
        refused += r->at("status") == "refused";
        stable_at_max += r->at("status") == "stable-at-max";
        if (r->at("status") != "bracketed") continue;
        if (auto v = number(r->at("h_w_max"))) hw.push_back(*v);
        if (auto v = number(r->at("ratio"))) ratio.push_back(*v);
      }
      json e = {{"engine", key},
                {"cells", groups[key].size()},
                {"refused", refused},
                {"stable_at_max", stable_at_max},
                {"bracketed", hw.size()}};
      if (!hw.empty()) {
        e["h_w_max_worst"] = *std::min_element(hw.begin(), hw.end());
        e["h_w_max_median"] = median(hw);
      }
      if (!ratio.empty()) e["ratio_worst"] = *std::min_element(ratio.begin(), ratio.end());
      engines.push_back(e);
    }
    scenes.push_back({{"scene", entry["scene"]}, {"mass_ratio", lowest}, {"engines", engines}});
  }
  return scenes;
}

}  // namespace

json reportHeadlines(const json& comparisons, const json& stability_scenes) {
  const json cloths = clothDisagreements(comparisons);
  return {{"worst_cloth_drape", cloths["rest"]},
          {"worst_moving_cloth", cloths["moving"]},
          {"cloth_states", cloths["states"]},
          {"ranking", ranking(comparisons)},
          {"verdicts", verdicts(comparisons, stability_scenes)},
          {"momentum", momentum(comparisons)},
          {"stability", stability(stability_scenes)}};
}

}  // namespace springcheck
