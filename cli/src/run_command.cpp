#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/io/run_output.h"

namespace springcheck {
namespace {

struct RunOptions {
  std::string scene_path;
  std::string engine = "mysim";
  std::string integrator;
  double dt = 0.0;
  double duration = 0.0;
  int classic_iterations = 0;
  std::string out;
  bool obj_frames = false;
  std::vector<std::string> engines_files;
  Timing timing;
};

int runScene(const RunOptions& o) {
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  auto scene = loadSceneOrSay(*registry, o.scene_path, o.dt, o.duration);
  if (!scene) return kBadInput;
  // Flags override the scene; they are checked as the file's fields would be.
  if (!o.integrator.empty()) {
    auto name = mysim::canonicalIntegratorName(o.integrator);
    if (!name) {
      std::cerr << "error: --integrator: " << name.error() << '\n';
      return kBadInput;
    }
    scene->integrator.name = *name;
  }
  if (o.classic_iterations > 0) {
    scene->engine_settings["bullet"]["classic_iterations"] = o.classic_iterations;
  }
  RunConfig config = runConfig(*scene);
  applyTiming(o.timing, config);
  const mysim::Model model = mysim::buildModel(*scene);
  auto record = registry->run(o.engine, model, config);
  if (!record) {
    const bool overridden = o.dt > 0 || o.duration > 0;
    std::cerr << "error: " << record.error().message
              << (record.error().kind == EngineError::Kind::Invalid && overridden
                      ? " (with the --dt / --duration given)"
                      : "")
              << '\n';
    return exitCodeFor(record.error());
  }
  const std::string dir = o.out.empty() ? "out/" + scene->name + "/" + o.engine : o.out;
  if (auto written = writeRunOutputs(dir, model, config.scene_name, config.source, *record,
                                     {.obj_frames = o.obj_frames});
      !written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << scene->name << " [" << o.engine << ", " << record->integrator << ", dt "
            << record->dt << " s]: " << record->steps << " steps in " << record->wall_seconds
            << " s ("
            << (record->threads > 0 ? std::to_string(record->threads) + " thread" +
                                          (record->threads > 1 ? "s" : "")
                                    : std::string("its own threads"))
            << ", fastest of " << record->repeats << "; " << record->realtimeFactor()
            << "x realtime) -> " << dir << '\n';
  if (record->blowup) {
    std::cerr << record->status() << ": t = " << record->blowup->time << " s (step "
              << record->blowup->step << "), " << record->blowup->check << ": "
              << record->blowup->detail << '\n';
  } else if (record->status() != "ok") {
    std::cerr << record->status() << ": " << record->counts.solver_failures
              << " steps' solves stopped short of their tolerance (the integrator's iteration "
                 "limit and tolerance: `springcheck list` names its fields)\n";
  }
  return exitCodeForStatus(record->status());
}

}  // namespace

void addRunCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "Run one scene and write its results");
  run->add_option("scene", options->scene_path, "Scene file (JSON)")->required();
  run->add_option("--engine", options->engine, "Engine to run the scene in")->capture_default_str();
  addEnginesFileOption(run, options->engines_files);
  run->add_option("--integrator", options->integrator, "Integrator (overrides the scene)");
  run->add_option("--dt", options->dt, "Step in s (overrides the scene)")->check(kPositive);
  run->add_option("--duration", options->duration, "Duration in s (overrides the scene)")
      ->check(kPositive);
  run->add_option("--classic-iterations", options->classic_iterations,
                  "bullet-classic solver passes per step (overrides bullet.classic_iterations)")
      ->check(CLI::Range(1, 10000));
  run->add_option("--out", options->out, "Output directory (default out/SCENE/ENGINE)");
  run->add_flag("--obj-frames", options->obj_frames,
                "Also write every sampled frame as OUT/obj/frame_NNNNN.obj (with normals; "
                "obj/times.csv gives each frame's time), for Blender, MeshLab or ParaView");
  addTimingOptions(run, options->timing, 1);
  run->callback([options, &exit_code] { exit_code = runScene(*options); });
}

}  // namespace springcheck
