#include <cstdio>
#include <iostream>

#include "commands.h"
#include "data_dir.h"

namespace springcheck {

void addEnginesFileOption(CLI::App* command, std::vector<std::string>& files) {
  command->add_option("--engines-file", files,
                      "Engines file adding your own simulators as engines "
                      "(docs/external-engines.md); repeatable. Built in: " +
                          engineList(EngineRegistry()));
}

std::optional<EngineRegistry> makeRegistry(const std::vector<std::string>& files) {
  EngineRegistry registry;
  registry.setShippedScenes(dataFile("scenes"));
  for (const std::string& file : files) {
    if (auto added = registry.addEnginesFile(file); !added) {
      std::cerr << "error: --engines-file: " << added.error() << '\n';
      return std::nullopt;
    }
  }
  return registry;
}

std::optional<mysim::Scene> loadSceneOrSay(const EngineRegistry& registry, const std::string& path,
                                           double dt, double duration) {
  auto scene = registry.loadScene(path);
  if (!scene) {
    std::cerr << "error: " << scene.error() << '\n';
    return std::nullopt;
  }
  if (dt > 0.0) scene->dt = dt;
  if (duration > 0.0) scene->duration = duration;
  return std::move(*scene);
}

void addTimingOptions(CLI::App* command, Timing& timing, int default_repeats) {
  timing.repeats = default_repeats;
  command
      ->add_option("--repeats", timing.repeats,
                   "Time every run this many times; wall times are the fastest (the median is "
                   "kept beside it)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command
      ->add_option("--threads", timing.threads,
                   "OpenMP threads per mysim run (default: every core, or OMP_NUM_THREADS)")
      ->check(CLI::Range(1, 1024));
  command->add_flag("--fixed-threads", timing.fixed_threads,
                    "Keep the thread count even when other processes hold cores (by default a "
                    "run steps on the cores the rest of the machine leaves free)");
}

int exitCodeForStatus(const std::string& status) {
  if (status == "ok") return kOk;
  if (status == "blowup") return kBlowUp;
  return kSolverLimit;
}

bool parseShard(const std::string& text, int& index, int& count) {
  if (std::sscanf(text.c_str(), "%d/%d", &index, &count) != 2 || count < 1 || index < 0 ||
      index >= count) {
    std::cerr << "error: --shard: expected i/n with 0 <= i < n, got " << text << '\n';
    return false;
  }
  return true;
}

int exitCodeFor(const EngineError& error) {
  return error.kind == EngineError::Kind::Failed ? kEngineFailed : kBadInput;
}

}  // namespace springcheck
