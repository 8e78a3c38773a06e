#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/engines/python_interpreter.h"
#include "compare/io/atomic_file.h"
#include "compare/io/report_manifest.h"
#include "data_dir.h"
#include "springcheck_commit.h"

namespace springcheck {
namespace {

// Writes the manifest of what the results folder holds (compare/report_manifest.h), then runs
// reports/make_report.py (found beside the executable, data_dir.h) on it with a python3 that has
// matplotlib, found now (python_interpreter.h): C++ writes and finds the tables, Python only
// draws them.
int report(const std::string& results, const std::string& out) {
  const auto found = findPython({"numpy", "matplotlib"});
  if (!found) {
    std::cerr << "error: springcheck report draws with matplotlib: " << found.error() << '\n';
    return kFailure;
  }
  const std::string& python = *found;
  const std::string script = dataFile("reports/make_report.py");
  if (access(script.c_str(), R_OK) != 0) {
    std::cerr << "error: the report script " << script
              << " is missing (set SPRINGCHECK_DATA_DIR to the folder holding reports/)\n";
    return kFailure;
  }
  if (!std::filesystem::is_directory(results)) {
    std::cerr << "error: --results: " << results
              << " is not a folder (the commands that fill it: springcheck report --help)\n";
    return kBadInput;
  }
  const ReportStamp stamp{SPRINGCHECK_VERSION, SPRINGCHECK_COMMIT,
                          "springcheck report --results " + results + " --out " + out, dataDir()};
  // Every built-in engine spec, mysim once per integrator: the series with fixed styles.
  const EngineRegistry builtin;
  std::vector<ReportSeries> series;
  for (const std::string& spec : builtin.specs()) {
    series.push_back({spec, builtin.find(spec.substr(0, spec.find(':')))->kind});
  }
  auto manifest = reportManifest(results, stamp, series);
  if (!manifest) {
    std::cerr << "error: " << manifest.error() << '\n';
    return kBadInput;
  }
  const std::string manifest_path = out + "/manifest.json";
  std::error_code error;
  std::filesystem::create_directories(out, error);
  if (auto written = writeFileAtomically(
          manifest_path, [&](std::ostream& file) { file << jsonText(*manifest, 2) << '\n'; });
      !written) {
    std::cerr << "error: --out: " << written.error() << '\n';
    return kFailure;
  }
  const pid_t child = fork();
  if (child == 0) {
    execl(python.c_str(), python.c_str(), script.c_str(), "--manifest", manifest_path.c_str(),
          "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) < 0) return kFailure;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return kFailure;
  if (const auto& missing = (*manifest)["missing"]; !missing.empty()) {
    std::cerr << "report: " << missing.size()
              << " inputs missing; its page 'Missing inputs' names the command that makes each\n";
  }
  return kOk;
}

}  // namespace

void addReportCommand(CLI::App& app, int& exit_code) {
  auto results = std::make_shared<std::string>("out");
  auto out = std::make_shared<std::string>("out/report");
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Draw report.pdf and one PNG per page from whatever result tables exist (pages for missing "
      "ones name the command that makes them)");
  cmd->add_option("--results", *results,
                  "Folder of result tables (gate.json, sweep/, "
                  "recommend/, stability/, suite/, energy/, bench/)")
      ->capture_default_str();
  cmd->add_option("--out", *out, "Report folder (report.pdf, PNGs, manifest.json)")
      ->capture_default_str();
  cmd->callback([results, out, &exit_code] { exit_code = report(*results, *out); });
}

}  // namespace springcheck
