#pragma once
// Reading the study tables the report's headlines are found from (internal to compare/io): a
// CSV by column name, a JSON file, a finite number, and a comparison's state at its last frame.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace springcheck::report_tables {

using Row = std::map<std::string, std::string>;

// The rows of a CSV table by column name; none if the file is missing or not a regular file (a
// FIFO would block). Rows whose field count differs from the header's are skipped.
std::vector<Row> readTable(const std::string& path);
// The JSON in a regular file, or null if it is missing or not JSON.
nlohmann::json readJson(const std::string& file);
// A finite number from a table cell, or nothing.
std::optional<double> number(const std::string& text);
// A finite number at `key` of a JSON object, or nothing.
std::optional<double> numberIn(const nlohmann::json& j, const char* key);
double median(std::vector<double> v);
// A comparison's state at its last frame: settled (every engine's kinetic energy stayed below
// 1e-4 of its peak from some time on, the latest such time, at most 90 % into the run: one that
// got there in the last tenth has not shown it stays), driven (wind or moving pins: it never
// rests), or still moving at the end; with the last frame's time.
nlohmann::json lastFrameState(const nlohmann::json& comparison);

// A comparison the manifest lists, read once for every headline: its manifest entry (group,
// scene, folder), its comparison.json and its state at the last frame.
struct LoadedComparison {
  const nlohmann::json* entry;
  nlohmann::json record;
  nlohmann::json state;
  const nlohmann::json& operator[](const char* key) const { return (*entry)[key]; }
};
// Every comparison of the manifest whose comparison.json reads (the others are left out).
std::vector<LoadedComparison> loadComparisons(const nlohmann::json& comparisons);

}  // namespace springcheck::report_tables
