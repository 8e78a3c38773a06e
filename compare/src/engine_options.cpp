#include <iostream>

#include "commands.h"

namespace springcheck {

void addEnginesFileOption(CLI::App* command, std::vector<std::string>& files) {
  command->add_option("--engines-file", files,
                      "Engines file adding your own simulators as engines "
                      "(docs/external-engines.md); repeatable. Built in: " +
                          engineList(EngineRegistry()));
}

std::optional<EngineRegistry> makeRegistry(const std::vector<std::string>& files) {
  EngineRegistry registry;
  for (const std::string& file : files) {
    if (auto added = registry.addEnginesFile(file); !added) {
      std::cerr << "error: --engines-file: " << added.error() << '\n';
      return std::nullopt;
    }
  }
  return registry;
}

int exitCodeForStatus(const std::string& status) {
  if (status == "ok") return kOk;
  if (status == "blowup") return kBlowUp;
  return kSolverLimit;
}

int exitCodeFor(const EngineError& error) {
  return error.kind == EngineError::Kind::Failed ? kEngineFailed : kBadInput;
}

}  // namespace springcheck
