#pragma once
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <string>

namespace springcheck {

// Exit codes of the springcheck executable.
enum ExitCode : int { kOk = 0, kFailure = 1, kBadInput = 2, kBlowUp = 3 };

// A flag value that must be a number > 0 (CLI11's PositiveNumber prints its whole double range).
inline const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(value > 0.0)) {
        return "expected a number > 0, got " + text;
      }
      return "";
    },
    "> 0");

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
