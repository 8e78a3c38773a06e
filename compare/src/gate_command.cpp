#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/gate.h"

namespace springcheck {

void addGateCommand(CLI::App& app, int& exit_code) {
  auto path = std::make_shared<std::string>("compare/tolerances.json");
  CLI::App* cmd = app.add_subcommand("gate", "Check every bound of a tolerances file");
  cmd->add_option("--tolerances", *path, "Tolerances file")->capture_default_str();
  cmd->callback([path, &exit_code] {
    auto tolerances = loadTolerances(*path);
    if (!tolerances) {
      std::cerr << "error: " << tolerances.error() << '\n';
      exit_code = kBadInput;
      return;
    }
    const GateReport report = runGate(*tolerances);
    printGate(std::cout, report);
    exit_code = report.passed() ? kOk : kFailure;
  });
}

}  // namespace springcheck
