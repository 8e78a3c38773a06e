#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "compare/io/text_format.h"
#include "compare/studies/comparison.h"

namespace springcheck {
namespace {

struct CompareOptions {
  std::string scene_path;
  std::string engines;  // empty: every engine of the registry
  std::string out;
  double dt = 0.0, duration = 0.0;  // 0: the scene's
  bool obj_frames = false;
  std::vector<std::string> engines_files;
  Timing timing;
  std::string integrator;  // refused: compare names integrators in its engine specs
};

int compare(const CompareOptions& o) {
  if (!o.integrator.empty()) {
    const std::string name = mysim::clip(o.integrator, 40);
    std::cerr << "error: --integrator: compare runs several engines, so it names mysim's "
                 "integrator in each engine: write --engines mysim:"
              << name << " (several: --engines mysim:rk4,mysim:" << name
              << ",bullet-implicit); `springcheck run` takes --integrator\n";
    return kBadInput;
  }
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  auto scene = loadSceneOrSay(*registry, o.scene_path, o.dt, o.duration);
  if (!scene) return kBadInput;
  const std::vector<std::string> engines =
      o.engines.empty() ? registry->names() : registry->expand(splitList(o.engines));
  auto comparison = compareScene(*registry, *scene, engines, o.timing);
  if (!comparison) {
    std::cerr << "error: " << comparison.error() << '\n';
    return kBadInput;
  }
  printComparison(std::cout, *comparison);
  const std::string dir = o.out.empty() ? "out/compare/" + scene->name : o.out;
  if (auto written = writeComparison(dir, *comparison, {.obj_frames = o.obj_frames}); !written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << "results in " << dir << '\n';
  if (!comparison->failed.empty()) return kEngineFailed;
  // A blow-up outranks a solver limit: it is the stronger statement about a run.
  int code = kOk;
  for (const EngineMetrics& m : comparison->engines) {
    if (m.status == "blowup") return kBlowUp;
    if (m.status != "ok") code = kSolverLimit;
  }
  return code;
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Run a scene in several engines and compare");
  cmd->add_option("scene", o->scene_path, "Scene file (JSON)")->required();
  cmd->add_option(
      "--engines", o->engines,
      "Comma-separated engines (default: every engine, your own included; all: every engine with "
      "mysim once per integrator; all-fixed-step: the same without adaptive ones)");
  addEnginesFileOption(cmd, o->engines_files);
  cmd->add_option("--dt", o->dt, "Step in s for every engine (overrides the scene)")
      ->check(kPositive);
  cmd->add_option("--duration", o->duration, "Duration in s (overrides the scene)")
      ->check(kPositive);
  cmd->add_option("--out", o->out, "Output directory (default out/compare/SCENE)");
  cmd->add_flag("--obj-frames", o->obj_frames,
                "Also write every sampled frame of each engine as ENGINE/obj/frame_NNNNN.obj "
                "(with normals), for Blender, MeshLab or ParaView");
  addTimingOptions(cmd, o->timing, 1);
  // Not an option of compare: taken only to say what to write instead (hidden from --help).
  cmd->add_option("--integrator", o->integrator)->group("");
  cmd->callback([o, &exit_code] { exit_code = compare(*o); });
}

}  // namespace springcheck
