#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <tuple>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/studies/gate.h"
#include "compare/studies/gate_ablation.h"
#include "compare/studies/gate_report_formats.h"
#include "data_dir.h"

namespace springcheck {
namespace {

// gate --ablate: prints each term's effect, warns of those the scenes carry but do not need.
bool warnOfUnneededTerms(const EngineRegistry& registry, const GateReport& report) {
  const auto effects = ablateGate(registry, report);
  if (!effects) {
    std::cerr << "error: --ablate: " << effects.error() << '\n';
    return false;
  }
  printGateAblation(std::cout, *effects);
  for (const GateTermEffect& e : *effects) {
    if (!e.droppable()) continue;
    std::cerr << "warning: " << e.scene << " carries " << e.term << " but every gated check "
              << "holds without it, within its bound; drop it, or declare it in the scene's "
              << "\"needs\" (docs/trade.md)\n";
  }
  return true;
}

}  // namespace

void addGateCommand(CLI::App& app, int& exit_code) {
  auto path = std::make_shared<std::string>(dataFile("compare/tolerances.json"));
  auto json_out = std::make_shared<std::string>();
  auto junit_out = std::make_shared<std::string>();
  auto markdown_out = std::make_shared<std::string>();
  auto engines_files = std::make_shared<std::vector<std::string>>();
  auto ablate = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("gate", "Check every bound of a tolerances file");
  cmd->add_option("--tolerances", *path, "Tolerances file")->capture_default_str();
  cmd->add_option("--json", *json_out, "Also write every check's result to this JSON file");
  cmd->add_option("--junit", *junit_out,
                  "Also write JUnit XML here: one test case per check, failures with the "
                  "measured value, the bound and its reason (for CI systems)");
  cmd->add_option("--markdown", *markdown_out,
                  "Also write a markdown table here (failures first), for a pull-request comment");
  cmd->add_flag("--ablate", *ablate,
                "Then rerun each scene with each model term it carries taken out and warn of a "
                "term no check needs (every check still passes, each within its bound) that the "
                "scene's \"needs\" do not declare (docs/trade.md)");
  addEnginesFileOption(cmd, *engines_files);
  cmd->callback([path, json_out, junit_out, markdown_out, engines_files, ablate, &exit_code] {
    std::optional<EngineRegistry> registry = makeRegistry(*engines_files);
    if (!registry) {
      exit_code = kBadInput;
      return;
    }
    auto tolerances = loadTolerances(*path, *registry);
    if (!tolerances) {
      std::cerr << "error: " << tolerances.error() << '\n';
      exit_code = kBadInput;
      return;
    }
    const auto gate = runGate(*registry, *tolerances);
    if (!gate) {
      std::cerr << "error: " << gate.error() << '\n';
      exit_code = kBadInput;
      return;
    }
    const GateReport& report = *gate;
    printGate(std::cout, report);
    for (const auto& [file, flag, write] :
         {std::tuple{*json_out, "--json", &writeGateJson},
          std::tuple{*junit_out, "--junit", &writeJunit},
          std::tuple{*markdown_out, "--markdown", &writeGateMarkdown}}) {
      if (file.empty()) continue;
      if (auto written =
              writeFileAtomically(file, [&](std::ostream& out) { write(out, report, *path); });
          !written) {
        std::cerr << "error: " << flag << ": " << written.error() << '\n';
        exit_code = kFailure;
        return;
      }
    }
    exit_code = report.passed() ? kOk : kFailure;
    if (*ablate && !warnOfUnneededTerms(*registry, report)) exit_code = kBadInput;
  });
}

}  // namespace springcheck
