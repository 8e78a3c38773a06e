#include "compare/io/report_headlines.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "engine_verdicts.h"
#include "report_tables.h"

namespace springcheck {
namespace {

using nlohmann::json;
using namespace report_tables;

// Final-frame distances mean a disagreement of rest shapes only where every engine has settled:
// the largest there (mirror-aware: a fold buckled the other way is not a disagreement), and,
// apart, the largest trajectory difference on cloths still moving or driven at the end.
json clothDisagreements(const std::vector<LoadedComparison>& comparisons) {
  json rest, moving, states = json::object();
  for (const LoadedComparison& c : comparisons) {
    if (c["group"] == "energy") continue;
    const json& j = c.record;
    if (j["model"].value("kind", "") != "cloth") continue;
    const json& state = c.state;
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

// One picture ranking the engines by scene: for each suite scene, each engine's error against the
// closed form where the scene has one, else its distance to the scene's first engine (mysim at the
// scene's integrator): the rest shape (mirror-aware) where every engine settled, the trajectory
// otherwise; each scene marked settled, moving or driven.
json ranking(const std::vector<LoadedComparison>& comparisons) {
  json scenes = json::array();
  for (const LoadedComparison& c : comparisons) {
    if (c["group"] != "suite") continue;
    const json& j = c.record;
    if (j["engines"].empty()) continue;
    const json& state = c.state;
    json values = json::object();
    std::string measure;
    bool closed = false;
    for (const json& e : j["engines"]) closed |= numberIn(e, "closed_form_error").has_value();
    std::string unit = "m";
    if (closed) {
      measure = "closed form";
      for (const json& e : j["engines"]) {
        if (const auto v = numberIn(e, "closed_form_error")) values[e["engine"].get<std::string>()] = *v;
        if (e.contains("closed_form")) unit = e["closed_form"].value("unit", unit);
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
    scenes.push_back({{"scene", c["scene"]}, {"state", state}, {"measure", measure}, {"unit", unit},
                      {"values", values}, {"not_ok", blown}});
  }
  return scenes;
}

// Each free body of the suite: its worst linear and its worst angular drift, each with its own
// engine.
json momentum(const std::vector<LoadedComparison>& comparisons) {
  json list = json::array();
  for (const LoadedComparison& c : comparisons) {
    if (c["group"] != "suite") continue;
    const json& j = c.record;
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

// One engine's cells of a stability map: how many, refused, stable at the largest step tried,
// bracketed; the worst (lowest) and median h w_max of those bracketed and the worst and best
// measured / theory.
json stabilityCells(const std::string& key, const std::vector<const Row*>& cells) {
  std::vector<double> hw, ratio;
  int refused = 0, stable_at_max = 0;
  for (const Row* r : cells) {
    refused += r->at("status") == "refused";
    stable_at_max += r->at("status") == "stable-at-max";
    if (r->at("status") != "bracketed") continue;
    if (auto v = number(r->at("h_w_max"))) hw.push_back(*v);
    if (auto v = number(r->at("ratio"))) ratio.push_back(*v);
  }
  json e = {{"engine", key},
            {"cells", cells.size()},
            {"refused", refused},
            {"stable_at_max", stable_at_max},
            {"bracketed", hw.size()}};
  if (!hw.empty()) {
    e["h_w_max_worst"] = *std::min_element(hw.begin(), hw.end());
    e["h_w_max_median"] = median(hw);
  }
  if (!ratio.empty()) {
    e["ratio_worst"] = *std::min_element(ratio.begin(), ratio.end());
    e["ratio_best"] = *std::max_element(ratio.begin(), ratio.end());
  }
  return e;
}

// Per scene map: every engine (bullet-classic per pass count) over every cell mapped (every
// stiffness scale and mass ratio: a worst cell is the worst of all, the ratios listed with it).
json stability(const json& stability_scenes) {
  json scenes = json::array();
  for (const json& entry : stability_scenes) {
    const std::vector<Row> rows = readTable(entry["path"]);
    std::map<std::string, std::vector<const Row*>> groups;
    std::vector<std::string> order;
    std::vector<double> ratios;
    for (const Row& r : rows) {
      const std::string key =
          r.at("engine") +
          (r.at("classic_iterations").empty() ? "" : " (" + r.at("classic_iterations") + ")");
      if (!groups.count(key)) order.push_back(key);
      groups[key].push_back(&r);
      const double ratio = number(r.at("mass_ratio")).value_or(NAN);
      if (std::find(ratios.begin(), ratios.end(), ratio) == ratios.end()) ratios.push_back(ratio);
    }
    std::sort(ratios.begin(), ratios.end());
    json engines = json::array();
    for (const std::string& key : order) engines.push_back(stabilityCells(key, groups[key]));
    scenes.push_back({{"scene", entry["scene"]}, {"mass_ratios", ratios}, {"engines", engines}});
  }
  return scenes;
}

}  // namespace

json reportHeadlines(const json& comparison_entries, const json& stability_scenes) {
  // Each comparison.json read once, for every headline below.
  const std::vector<LoadedComparison> comparisons = loadComparisons(comparison_entries);
  const json cloths = clothDisagreements(comparisons);
  return {{"worst_cloth_drape", cloths["rest"]},
          {"worst_moving_cloth", cloths["moving"]},
          {"cloth_states", cloths["states"]},
          {"ranking", ranking(comparisons)},
          {"verdicts", engineVerdicts(comparisons, stability_scenes)},
          {"momentum", momentum(comparisons)},
          {"stability", stability(stability_scenes)}};
}

}  // namespace springcheck
