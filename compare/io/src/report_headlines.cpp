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

// Settled shapes only (the cloths, which have drape pages): a swinging chain's last frames part
// by chaos, not by disagreement.
json worstClothDrape(const json& comparisons) {
  json worst;
  for (const json& c : comparisons) {
    if (c["group"] == "energy" || c["pair_metrics"].is_null()) continue;
    if (c["model"].value("kind", "") != "cloth") continue;
    for (const Row& p : readTable(c["pair_metrics"])) {
      const auto v = number(p.count("drape_max") ? p.at("drape_max") : "");
      if (v && (worst.is_null() || *v > worst["value"].get<double>())) {
        worst = {{"value", *v},
                 {"a", p.at("a")},
                 {"b", p.at("b")},
                 {"scene", c["scene"]},
                 {"group", c["group"]}};
      }
    }
  }
  return worst;
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
  return {{"worst_cloth_drape", worstClothDrape(comparisons)},
          {"momentum", momentum(comparisons)},
          {"stability", stability(stability_scenes)}};
}

}  // namespace springcheck
