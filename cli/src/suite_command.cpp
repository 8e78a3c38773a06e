#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/io/scene_files.h"
#include "compare/studies/comparison.h"
#include "compare/studies/gate.h"
#include "data_dir.h"

namespace springcheck {
namespace {

struct SuiteOptions {
  std::string dir = dataFile("scenes");
  std::string out = "out/suite";
  std::vector<std::string> engines_files;
  Timing timing;
  std::string tolerances;  // also gate the runs against this file
};

// Every scene under a directory in every engine that takes it (every engine of the registry,
// the user's own included; an engine that refuses a scene says why, and that is listed), with
// the comparison table of each. A scene file that does not load, a run that blows up or an
// external engine that fails makes the suite fail; the other scenes still run.
int runSuite(const SuiteOptions& o) {
  std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  auto files = sceneFiles(o.dir);
  if (!files) {
    std::cerr << "error: " << files.error() << '\n';
    return kBadInput;
  }
  std::optional<Tolerances> tolerances;
  if (!o.tolerances.empty()) {
    auto loaded = loadTolerances(o.tolerances, *registry);
    if (!loaded) {
      std::cerr << "error: --tolerances: " << loaded.error() << '\n';
      return kBadInput;
    }
    tolerances = std::move(*loaded);
  }
  int code = kOk;
  ComparisonCache done;
  for (const std::string& file : *files) {
    auto scene = registry->loadScene(file);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      code = kBadInput;
      continue;
    }
    auto comparison = compareScene(*registry, *scene, registry->names(), o.timing);
    if (!comparison) {
      std::cerr << "error: " << comparison.error() << '\n';
      code = kBadInput;
      continue;
    }
    printComparison(std::cout, *comparison);
    if (!comparison->failed.empty() && code == kOk) code = kEngineFailed;
    if (auto written = writeComparison(o.out + "/" + scene->name, *comparison); !written) {
      std::cerr << "error: " << written.error() << '\n';
      code = kFailure;
    }
    for (const EngineMetrics& m : comparison->engines) {
      // The seed scenes run at the seed's own (stable) settings: a blow-up there is a bug.
      if (m.status != "ok" && code == kOk) code = exitCodeForStatus(m.status);
    }
    std::cout << '\n';
    std::error_code ec;
    if (tolerances) done.emplace(std::filesystem::weakly_canonical(file, ec).string(), *comparison);
  }
  if (tolerances) {
    const auto report = runGate(*registry, *tolerances, done);
    if (!report) {
      std::cerr << "error: gate: " << report.error() << '\n';
      return kBadInput;
    }
    printGate(std::cout, *report);
    if (!report->passed() && code == kOk) code = kFailure;
  }
  std::cout << "results in " << o.out << "/<scene>/\n";
  return code;
}

}  // namespace

void addSuiteCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SuiteOptions>();
  CLI::App* suite = app.add_subcommand(
      "suite", "Run every scene under a directory in every engine that takes it, and compare");
  suite->add_option("dir", options->dir, "Scene directory")->capture_default_str();
  suite->add_option("--out", options->out, "Output root")->capture_default_str();
  addEnginesFileOption(suite, options->engines_files);
  addTimingOptions(suite, options->timing, 1);
  suite->add_option("--tolerances", options->tolerances,
                    "Then check these bounds against the runs (a tolerances file, which may "
                    "name its own engines_file); the exit code says whether they held");
  suite->callback([options, &exit_code] { exit_code = runSuite(*options); });
}

}  // namespace springcheck
