#include <sys/wait.h>
#include <unistd.h>

#include <iostream>
#include <memory>

#include "commands.h"
#include "data_dir.h"

namespace springcheck {
namespace {

// Runs reports/make_report.py (found beside the executable, data_dir.h) with the interpreter CMake found to have matplotlib: C++ writes
// the tables, Python only draws them.
int report(const std::string& results, const std::string& out) {
  const std::string python = SPRINGCHECK_PYTHON;
  if (python.empty()) {
    std::cerr << "error: no python3 with matplotlib and numpy was found when springcheck was "
                 "configured; install python3-matplotlib python3-numpy and re-run cmake\n";
    return kFailure;
  }
  const std::string script = dataFile("reports/make_report.py");
  if (access(script.c_str(), R_OK) != 0) {
    std::cerr << "error: the report script " << script
              << " is missing (set SPRINGCHECK_DATA_DIR to the folder holding reports/)\n";
    return kFailure;
  }
  const pid_t child = fork();
  if (child == 0) {
    execl(python.c_str(), python.c_str(), script.c_str(), "--results", results.c_str(),
          "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) < 0) return kFailure;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? kOk : kFailure;
}

}  // namespace

void addReportCommand(CLI::App& app, int& exit_code) {
  auto results = std::make_shared<std::string>("out");
  auto out = std::make_shared<std::string>("out/report");
  CLI::App* cmd = app.add_subcommand("report", "Draw report.pdf and PNGs from the result tables");
  cmd->add_option("--results", *results, "Directory of result tables")->capture_default_str();
  cmd->add_option("--out", *out, "Report directory")->capture_default_str();
  cmd->callback([results, out, &exit_code] { exit_code = report(*results, *out); });
}

}  // namespace springcheck
