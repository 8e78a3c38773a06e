#include "report_tables.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "compare/io/csv.h"

namespace springcheck::report_tables {

using nlohmann::json;

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

json lastFrameState(const json& comparison) {
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

std::vector<LoadedComparison> loadComparisons(const json& comparisons) {
  std::vector<LoadedComparison> loaded;
  for (const json& c : comparisons) {
    json record = readJson(c["folder"].get<std::string>() + "/comparison.json");
    if (record.is_null()) continue;
    json state = lastFrameState(record);
    loaded.push_back({&c, std::move(record), std::move(state)});
  }
  return loaded;
}

}  // namespace springcheck::report_tables
