#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "compare/gate.h"

namespace springcheck {

void addGateCommand(CLI::App& app, int& exit_code) {
  auto path = std::make_shared<std::string>("compare/tolerances.json");
  auto json_out = std::make_shared<std::string>();
  auto engines_files = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = app.add_subcommand("gate", "Check every bound of a tolerances file");
  cmd->add_option("--tolerances", *path, "Tolerances file")->capture_default_str();
  cmd->add_option("--json", *json_out, "Also write every check's result to this JSON file");
  addEnginesFileOption(cmd, *engines_files);
  cmd->callback([path, json_out, engines_files, &exit_code] {
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
    const GateReport report = runGate(*registry, *tolerances);
    printGate(std::cout, report);
    if (!json_out->empty()) {
      nlohmann::json results = nlohmann::json::array();
      for (const CheckResult& r : report.results) {
        results.push_back(
            {{"scene", r.check.scene},
             {"engines", r.check.engines},
             {"metric", r.check.metric},
             {"bound", r.check.bound},
             {"why", r.check.why},
             {"passed", r.passed},
             {"problem", r.problem},
             {"measured", r.measured ? nlohmann::json(*r.measured) : nlohmann::json()}});
      }
      std::ofstream(*json_out) << nlohmann::json{{"tolerances", *path}, {"checks", results}}.dump(2)
                               << '\n';
    }
    exit_code = report.passed() ? kOk : kFailure;
  });
}

}  // namespace springcheck
