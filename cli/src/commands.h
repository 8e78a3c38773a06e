#pragma once
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"

namespace springcheck {

// Exit codes of the springcheck executable (README). kEngineFailed: an external engine crashed,
// timed out or returned a result that failed its checks. kSolverLimit: an adaptive integrator
// stopped the run at its step limits, or a linear solve stopped short of its tolerance.
enum ExitCode : int {
  kOk = 0,
  kFailure = 1,
  kBadInput = 2,
  kBlowUp = 3,
  kEngineFailed = 4,
  kSolverLimit = 5
};

// The exit code a finished run's status calls for ("ok", "blowup", "step-limit", ...).
int exitCodeForStatus(const std::string& status);

// --engines-file FILE (repeatable): the user's own engines, for every command that takes
// engines. The option's help lists the built-in engines.
void addEnginesFileOption(CLI::App* command, std::vector<std::string>& files);
// The built-in registry plus those files; on a bad file prints the error and returns nothing.
std::optional<EngineRegistry> makeRegistry(const std::vector<std::string>& files);
// --shard i/n (sweep, trade): false after saying what was expected.
bool parseShard(const std::string& text, int& index, int& count);
// The exit code for an engine that did not run.
int exitCodeFor(const EngineError& error);

// --repeats, --threads, --fixed-threads (docs/timing.md).
void addTimingOptions(CLI::App* command, Timing& timing, int default_repeats);
// The scene at `path` with --dt and --duration applied (0: the scene's own), or nothing after
// printing the error (the file and field it names).
std::optional<mysim::Scene> loadSceneOrSay(const EngineRegistry& registry, const std::string& path,
                                           double dt = 0.0, double duration = 0.0);

// A flag value that must be a number > 0 (CLI11's PositiveNumber prints its whole double range).
inline const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(value > 0.0) || !std::isfinite(value)) {
        return "expected a finite number > 0, got " + text;
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
void addRecommendCommand(CLI::App& app, int& exit_code);
void addCompletionCommand(CLI::App& app, int& exit_code);
void addEngineCommand(CLI::App& app, int& exit_code);
void addRefineCommand(CLI::App& app, int& exit_code);
void addRoundoffCommand(CLI::App& app, int& exit_code);
void addCapstanCommand(CLI::App& app, int& exit_code);
void addTradeCommand(CLI::App& app, int& exit_code);
void addViewCommand(CLI::App& app, int& exit_code);  // only with SPRINGCHECK_HAS_VIEWER

}  // namespace springcheck
