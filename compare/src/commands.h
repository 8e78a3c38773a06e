#pragma once
#include <CLI/CLI.hpp>

namespace springcheck {

// Exit codes of the springcheck executable.
enum ExitCode : int { kOk = 0, kFailure = 1, kBadInput = 2, kBlowUp = 3 };

// Each registers a subcommand whose callback stores its exit code in `exit_code`.
void addRunCommand(CLI::App& app, int& exit_code);
void addListCommand(CLI::App& app, int& exit_code);
void addSuiteCommand(CLI::App& app, int& exit_code);
void addCompareCommand(CLI::App& app, int& exit_code);
void addGateCommand(CLI::App& app, int& exit_code);
void addSweepCommands(CLI::App& app, int& exit_code);
void addStabilityCommand(CLI::App& app, int& exit_code);
void addReportCommand(CLI::App& app, int& exit_code);
void addViewCommand(CLI::App& app, int& exit_code);  // only with SPRINGCHECK_HAS_VIEWER

}  // namespace springcheck
