#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/engines.h"
#include "compare/scene_files.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

int listAll(const std::string& dir) {
  std::cout << "Integrators:\n";
  for (const mysim::IntegratorInfo& info : mysim::integratorCatalog()) {
    std::cout << "  " << info.name << (info.alias.empty() ? "" : " (" + info.alias + ")") << "  "
              << info.description << '\n';
  }
  std::cout << "Engines:\n";
  for (const std::string& name : engineNames()) std::cout << "  " << name << '\n';
  std::cout << "Scenes in " << dir << ":\n";
  auto files = sceneFiles(dir);
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
    std::cout << "  " << file << "  " << mysim::systemKindName(scene->kind) << ", "
              << scene->integrator.name << ", dt " << scene->dt << " s: " << scene->description
              << '\n';
  }
  return code;
}

}  // namespace

void addListCommand(CLI::App& app, int& exit_code) {
  auto dir = std::make_shared<std::string>("scenes");
  CLI::App* list = app.add_subcommand("list", "List integrators, engines and scenes");
  list->add_option("dir", *dir, "Scene directory")->capture_default_str();
  list->callback([dir, &exit_code] { exit_code = listAll(*dir); });
}

}  // namespace springcheck
