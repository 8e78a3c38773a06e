#include "engine_verdicts.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "report_tables.h"

namespace springcheck {
namespace {

using nlohmann::json;
using namespace report_tables;

// One engine's error against a scene's closed form, with its unit, the exact value, the error
// relative to it (the error itself where it is already relative; none where the exact value is
// 0) and whether the engine meets the trust bound there.
json closedFormEntry(const json& engine, const json& scene, double error, double window) {
  const json& form = engine["closed_form"];
  const std::string unit = form.value("unit", "m");
  const double exact = form.value("exact", 0.0);
  json entry = {{"scene", scene}, {"value", error}, {"unit", unit}, {"window", window},
                {"quantity", form.value("quantity", "")}};
  if (unit == "rel") {
    entry["relative"] = error;
  } else if (exact != 0.0) {
    entry["relative"] = error / std::abs(exact);
  }
  entry["trusted"] = entry.contains("relative")
                         ? entry["relative"].get<double>() <= kTrustedRelativeError
                         : error <= kTrustedErrorAtRest;
  return entry;
}

// Orders closed-form misses worst first: runs that did not finish, then by relative error, those
// without one (exact 0) by their error in metres after.
bool worseMiss(const json& a, const json& b) {
  const bool fa = a.contains("status"), fb = b.contains("status");
  if (fa != fb) return fa;
  if (fa) return a["scene"].get<std::string>() < b["scene"].get<std::string>();
  const bool ra = a.contains("relative"), rb = b.contains("relative");
  if (ra != rb) return ra;
  const char* key = ra ? "relative" : "value";
  return a[key].get<double>() > b[key].get<double>();
}

struct Facts {
  std::map<std::string, json> by_engine;
  std::vector<std::string> order;
  // engine -> other engine -> its rest-shape distances on the settled cloths both ran
  std::map<std::string, std::map<std::string, std::vector<double>>> closeness;
};

// What one comparison says of each engine it ran.
void addComparison(Facts& facts, const json& scene, const json& comparison, const json& state) {
  const double window = state.value("last_frame", 0.0);
  // Energy is a conservation check only where nothing drives or damps the scene.
  const bool conservative =
      state["state"] != "driven" && !comparison["model"].value("damped", true);
  bool closed = false;  // the scene has a closed form (some engine was held to it)
  for (const json& e : comparison["engines"]) closed |= numberIn(e, "closed_form_error").has_value();
  for (const json& e : comparison["engines"]) {
    const std::string name = e["engine"];
    if (!facts.by_engine.count(name)) {
      facts.order.push_back(name);
      facts.by_engine[name] = {{"engine", name}};
    }
    json& v = facts.by_engine[name];
    auto worse = [&](const char* field, std::optional<double> value) {
      if (!value) return;
      if (!v.contains(field) || *value > v[field]["value"].get<double>()) {
        v[field] = {{"value", *value}, {"scene", scene}, {"window", window}};
      }
    };
    if (conservative) worse("energy_drift", numberIn(e, "energy_drift_max"));
    worse("linear_momentum", numberIn(e, "linear_momentum_drift"));
    worse("angular_momentum", numberIn(e, "angular_momentum_drift"));
    if (const auto error = numberIn(e, "closed_form_error"); error && e.contains("closed_form")) {
      v["closed_forms"].push_back(closedFormEntry(e, scene, *error, window));
    }
    if (e.value("status", "ok") != "ok") {
      v["not_ok"].push_back(scene);
      // A run that did not finish misses the scene's closed form: counted, never skipped.
      if (closed) {
        v["closed_forms"].push_back({{"scene", scene}, {"status", e["status"]}, {"window", window},
                                     {"blowup_time", e.value("blowup_time", json())},
                                     {"trusted", false}});
      }
    }
  }
}

void addCloseness(Facts& facts, const json& comparison, const json& state) {
  if (state["state"] != "settled") return;
  if (comparison["model"].value("kind", "") != "cloth") return;
  for (const json& p : comparison["pairs"]) {
    const auto d = numberIn(p, "drape_max_mirror_aware") ? numberIn(p, "drape_max_mirror_aware")
                                                         : numberIn(p, "drape_max");
    if (!d) continue;
    facts.closeness[p["a"]][p["b"]].push_back(*d);
    facts.closeness[p["b"]][p["a"]].push_back(*d);
  }
}

// Each engine's step rule on each mapped scene as written (stiffness scale 1, the lowest mass
// ratio): h < c / w_max with this scene's w_max, and the largest stable step measured.
std::map<std::string, json> stepRules(const json& stability_scenes) {
  std::map<std::string, json> rules;
  for (const json& entry : stability_scenes) {
    const std::vector<Row> rows = readTable(entry["path"]);
    double lowest = INFINITY;
    for (const Row& r : rows) lowest = std::min(lowest, number(r.at("mass_ratio")).value_or(INFINITY));
    for (const Row& r : rows) {
      if (number(r.at("mass_ratio")) != lowest || number(r.at("stiffness_scale")) != 1.0) continue;
      if (!r.at("classic_iterations").empty() && r.at("classic_iterations") != "10") continue;
      json rule = {{"scene", entry["scene"]}, {"status", r.at("status")}, {"mass_ratio", lowest}};
      for (const char* key : {"w_max", "theory_h", "h_stable"}) {
        if (auto v = number(r.at(key))) rule[key] = *v;
      }
      rules[r.at("engine")].push_back(rule);
    }
  }
  return rules;
}

// The closed forms' summary: how many scenes, how many within the trust bound, the misses worst
// first (runs that did not finish among them), and the worst error measured (its key number).
void summariseClosedForms(json& v) {
  if (!v.contains("closed_forms")) return;
  json misses = json::array();
  int trusted = 0;
  for (const json& entry : v["closed_forms"]) {
    if (entry["trusted"].get<bool>()) ++trusted;
    else misses.push_back(entry);
  }
  std::sort(misses.begin(), misses.end(), worseMiss);
  json measured = json::array();
  for (const json& entry : v["closed_forms"]) {
    if (!entry.contains("status")) measured.push_back(entry);
  }
  std::sort(measured.begin(), measured.end(), worseMiss);
  if (!measured.empty()) v["closed_form"] = measured.front();
  const std::size_t scenes = v["closed_forms"].size();
  v["closed_forms"] = {{"scenes", scenes}, {"trusted", trusted}, {"misses", misses}};
}

void addClosest(json& v, const std::map<std::string, std::vector<double>>& distances) {
  std::string nearest;
  double best = INFINITY;
  for (const auto& [other, d] : distances) {
    const double m = median(d);
    if (m < best) best = m, nearest = other;
  }
  if (nearest.empty()) return;
  v["closest"] = {{"engine", nearest}, {"median", best}, {"scenes", distances.at(nearest).size()}};
}

}  // namespace

json engineVerdicts(const std::vector<report_tables::LoadedComparison>& comparisons,
                    const json& stability_scenes) {
  Facts facts;
  for (const report_tables::LoadedComparison& c : comparisons) {
    if (c["group"] != "suite") continue;
    addComparison(facts, c["scene"], c.record, c.state);
    addCloseness(facts, c.record, c.state);
  }
  std::map<std::string, json> rules = stepRules(stability_scenes);
  json list = json::array();
  for (const std::string& name : facts.order) {
    json v = facts.by_engine[name];
    if (rules.count(name)) v["step_rules"] = rules[name];
    summariseClosedForms(v);
    addClosest(v, facts.closeness[name]);
    list.push_back(v);
  }
  return list;
}

}  // namespace springcheck
