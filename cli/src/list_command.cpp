#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <memory>

#include "commands.h"
#include "data_dir.h"
#include "compare/io/scene_files.h"
#include "compare/metrics/run_metrics.h"

namespace springcheck {
namespace {

struct ListOptions {
  std::string dir;  // empty: ./scenes where there is one (a checkout), else the shipped scenes
  std::vector<std::string> engines_files;
};

// ", stable for h w_max < 2" from the catalogue's undamped limit.
std::string stabilityText(const mysim::IntegratorInfo& info) {
  const std::optional<double> c = info.stable_h_omega(0.0);
  if (!c) return "";
  if (std::isinf(*c)) return ", stable at any step";
  if (*c == 0.0) return ", unstable without damping";
  std::ostringstream s;
  s.precision(3);
  s << ", stable for h w_max < " << *c;
  return s.str();
}

int listAll(const ListOptions& o) {
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  std::error_code error;
  const std::string dir = !o.dir.empty()                            ? o.dir
                          : std::filesystem::is_directory("scenes", error) ? std::string("scenes")
                                                                           : dataFile("scenes");
  std::cout << "Integrators:\n";
  for (const mysim::IntegratorInfo& info : mysim::integratorCatalog()) {
    std::cout << "  " << info.name << (info.alias.empty() ? "" : " (" + info.alias + ")") << "  "
              << info.description << "; " << mysim::familyName(info.family) << ", order "
              << info.order << stabilityText(info) << '\n';
    for (const mysim::IntegratorParameter& p : info.parameters) {
      std::cout << "      integrator." << p.name << " (default " << p.fallback << "): " << p.meaning
                << '\n';
    }
  }
  std::cout << "Metrics (for tolerances files' checks; docs/external-engines.md):\n";
  for (const MetricInfo& m : metricCatalog()) {
    std::cout << "  " << m.name << "  [" << m.unit << ", " << (m.pair ? "two engines" : "one engine")
              << "] " << m.description << '\n';
  }
  std::cout << "Engines:\n";
  for (const Engine& e : registry->engines()) {
    std::cout << "  " << e.name << (e.takes_integrator ? "[:INTEGRATOR]" : "") << "  (" << e.kind
              << ") " << e.description << '\n';
  }
  std::cout << "Scenes in " << dir << ":\n";
  auto files = sceneFiles(dir);
  if (!files) {
    std::cerr << "error: " << files.error() << '\n';
    return kBadInput;
  }
  int code = kOk;
  for (const std::string& file : *files) {
    auto scene = registry->loadScene(file);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      code = kBadInput;
      continue;
    }
    std::cout << "  " << file << "  " << mysim::systemType(*scene) << ", "
              << scene->integrator.name << ", dt " << scene->dt << " s: " << scene->description
              << '\n';
  }
  return code;
}

}  // namespace

void addListCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ListOptions>();
  CLI::App* list = app.add_subcommand("list", "List integrators, engines and scenes");
  list->add_option("dir", o->dir,
                   "Scene directory (default: ./scenes if there is one, else the scenes "
                   "springcheck ships, " + dataFile("scenes") + ")");
  addEnginesFileOption(list, o->engines_files);
  list->callback([o, &exit_code] { exit_code = listAll(*o); });
}

}  // namespace springcheck
