#pragma once
#include <expected>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace springcheck {

// What the report is drawn from, found by the side that wrote it: `springcheck report` scans the
// results folder and writes this manifest for reports/make_report.py, which reads nothing else
// to decide what exists. It lists every table present (the gate, sweeps and their
// recommendations, stability tables, every comparison folder with its scene's model facts and
// engines, benchmarks) and, for every input missing, the command that makes it, so the report
// shows that command on a page instead of failing. Output folder naming lives here, not in Python.
struct ReportStamp {
  std::string version, commit;
  std::string command;   // the command line that made the report
  std::string data_dir;  // springcheck's data (for the commands that make missing inputs)
};

// A built-in series the report gives a fixed style: an engine spec ("mysim:rk4",
// "bullet-classic") and its kind ("mysim" or another engine kind), in the registry's order, so
// the styles come from the catalogues, not from a list in Python.
struct ReportSeries {
  std::string key, kind;
};

// `results`: the results folder (springcheck report --results). Fails only on a comparison.json
// that cannot be read.
[[nodiscard]] std::expected<nlohmann::json, std::string> reportManifest(
    const std::string& results, const ReportStamp& stamp, const std::vector<ReportSeries>& series);

}  // namespace springcheck
