#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/comparison.h"
#include "compare/engines.h"
#include "compare/scene_files.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

struct SuiteOptions {
  std::string dir = "scenes";
  std::string out = "out/suite";
};

// Every scene under a directory in every engine that takes it (mysim always; the Bullet engines
// refuse what they cannot represent, and that is listed), with the comparison table of each.
// A scene file that does not load, or a run that blows up, makes the suite fail; the other
// scenes still run.
int runSuite(const SuiteOptions& o) {
  auto files = sceneFiles(o.dir);
  if (!files) {
    std::cerr << "error: " << files.error() << '\n';
    return kBadInput;
  }
  int code = kOk;
  for (const std::string& file : *files) {
    auto scene = mysim::loadScene(file);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      code = kBadInput;
      continue;
    }
    auto comparison = compareScene(*scene, engineNames());
    printComparison(std::cout, *comparison);
    if (auto written = writeComparison(o.out + "/" + scene->name, *comparison); !written) {
      std::cerr << "error: " << written.error() << '\n';
      code = kFailure;
    }
    for (const EngineMetrics& m : comparison->engines) {
      // The seed scenes run at the seed's own (stable) settings: a blow-up there is a bug.
      if (m.blew_up && code == kOk) code = kBlowUp;
    }
    std::cout << '\n';
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
  suite->callback([options, &exit_code] { exit_code = runSuite(*options); });
}

}  // namespace springcheck
