#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "compare/io/text_format.h"
#include "data_dir.h"
#include "viewer/window.h"

namespace springcheck {
namespace {

struct ViewOptions {
  std::string scene;
  std::string engines = "mysim,bullet-deformable";
  std::string integrator;
  double dt = 0.0;
  int frames = 0;
  std::string screenshot;
  std::string screenshot_dir;
  std::vector<std::string> engines_files;
};

int view(const ViewOptions& o) {
  std::optional<springcheck::EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  const std::vector<std::string> engines = springcheck::splitList(o.engines);
  if (!o.screenshot.empty() && o.frames <= 0) {
    std::cerr << "error: --screenshot needs --frames N\n";
    return kBadInput;
  }
  // The scenes `t` cycles through: the seed's systems and the cloth on the sphere.
  // They come with springcheck (data_dir.h), so the cycle works from any folder.
  std::vector<std::string> scenes;
  for (const char* name : {"seed/circle", "seed/pendulum", "matched/chain_swing",
                           "matched/cloth_hanging", "matched/cloth_on_sphere"}) {
    scenes.push_back(dataFile("scenes/" + std::string(name) + ".json"));
  }
  if (!o.integrator.empty()) {
    if (auto ok = mysim::canonicalIntegratorName(o.integrator); !ok) {
      std::cerr << "error: --integrator: " << ok.error() << '\n';
      return kBadInput;
    }
  }
  for (const std::string& e : engines) {
    if (auto known = registry->check(e); !known) {
      std::cerr << "error: --engines: " << known.error() << '\n';
      return kBadInput;
    }
  }
  viewer::ViewerSession session(
      *registry, scenes, o.scene, engines,
      o.integrator.empty() ? "" : *mysim::canonicalIntegratorName(o.integrator), o.dt);
  if (!session.error().empty()) {
    std::cerr << "error: " << session.error() << '\n';
    return kBadInput;
  }
  return viewer::runWindow(session, {1280, 640, o.frames, o.screenshot, o.screenshot_dir});
}

}  // namespace

void addViewCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand("view", "Watch a scene in mysim and Bullet side by side");
  cmd->add_option("scene", o->scene, "Scene file to show first")->required();
  cmd->add_option("--engines", o->engines, "Comma-separated engines, one viewport each")
      ->capture_default_str();
  cmd->add_option("--integrator", o->integrator, "mysim integrator (i cycles)");
  cmd->add_option("--dt", o->dt, "Step in s (overrides the scenes)")->check(kPositive);
  cmd->add_option("--frames", o->frames, "Run this many frames without a person, then close");
  cmd->add_option("--screenshot", o->screenshot, "With --frames: save the last frame as PNG");
  cmd->add_option("--screenshot-dir", o->screenshot_dir,
                  "Where the p key saves springcheck-view-NNN.png (default: the current folder)");
  addEnginesFileOption(cmd, o->engines_files);
  cmd->callback([o, &exit_code] { exit_code = view(*o); });
}

}  // namespace springcheck
