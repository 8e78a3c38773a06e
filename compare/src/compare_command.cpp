#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "compare/comparison.h"
#include "compare/engines.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

struct CompareOptions {
  std::string scene_path;
  std::string engines = "mysim,bullet-deformable,bullet-implicit,bullet-classic";
  std::string out;
};

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

int compare(const CompareOptions& o) {
  auto scene = mysim::loadScene(o.scene_path);
  if (!scene) {
    std::cerr << "error: " << scene.error() << '\n';
    return kBadInput;
  }
  auto comparison = compareScene(*scene, splitList(o.engines));
  if (!comparison) {
    std::cerr << "error: --engines: " << comparison.error() << '\n';
    return kBadInput;
  }
  printComparison(std::cout, *comparison);
  const std::string dir = o.out.empty() ? "out/compare/" + scene->name : o.out;
  if (auto written = writeComparison(dir, *comparison); !written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << "results in " << dir << '\n';
  for (const EngineMetrics& m : comparison->engines) {
    if (m.blew_up) return kBlowUp;
  }
  return kOk;
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Run a scene in several engines and compare");
  cmd->add_option("scene", o->scene_path, "Scene file (JSON)")->required();
  cmd->add_option("--engines", o->engines,
                  "Comma-separated engines (mysim, mysim:INTEGRATOR, bullet-...)")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output directory (default out/compare/SCENE)");
  cmd->callback([o, &exit_code] { exit_code = compare(*o); });
}

}  // namespace springcheck
