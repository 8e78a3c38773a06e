#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/engines.h"
#include "compare/run_output.h"
#include "compare/scene_files.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

struct SuiteOptions {
  std::string dir = "scenes";
  std::string out = "out/suite";
};

// Every scene through mysim at its own settings, one summary line each. A scene file that does
// not load, or a run that blows up, makes the suite fail (but the other scenes still run).
int runSuite(const SuiteOptions& o) {
  auto files = sceneFiles(o.dir);
  if (!files) {
    std::cerr << "error: " << files.error() << '\n';
    return kBadInput;
  }
  std::printf("%-22s %-9s %-16s %8s %7s %9s %12s %12s  %s\n", "scene", "system", "integrator",
              "dt [s]", "steps", "wall [ms]", "E start [J]", "E end [J]", "status");
  int code = kOk;
  for (const std::string& file : *files) {
    auto scene = mysim::loadScene(file);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      code = kBadInput;
      continue;
    }
    auto record = runEngine(*scene, "mysim");
    if (!record) {
      std::cerr << "error: " << record.error() << '\n';
      code = kBadInput;
      continue;
    }
    const std::string run_dir = o.out + "/" + scene->name + "/mysim";
    if (auto written = writeRunOutputs(run_dir, *scene, *record); !written) {
      std::cerr << "error: " << written.error() << '\n';
      code = kFailure;
      continue;
    }
    std::string status = "ok";
    if (record->blowup) {
      status = "BLOW-UP at t=" + std::to_string(record->blowup->time) + " s (" +
               record->blowup->check + ")";
      if (code == kOk) code = kBlowUp;
    }
    const bool has_energy = !record->energies.empty();
    std::printf("%-22s %-9s %-16s %8.4g %7ld %9.2f %12s %12s  %s\n", scene->name.c_str(),
                mysim::systemKindName(scene->kind), record->integrator.c_str(), record->dt,
                record->steps, 1e3 * record->wall_seconds,
                has_energy ? std::to_string(record->energies.front().total()).c_str() : "-",
                has_energy ? std::to_string(record->energies.back().total()).c_str() : "-",
                status.c_str());
  }
  std::printf("results in %s/<scene>/mysim\n", o.out.c_str());
  return code;
}

}  // namespace

void addSuiteCommand(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SuiteOptions>();
  CLI::App* suite = app.add_subcommand("suite", "Run every scene of a directory through mysim");
  suite->add_option("dir", options->dir, "Scene directory")->capture_default_str();
  suite->add_option("--out", options->out, "Output root")->capture_default_str();
  suite->callback([options, &exit_code] { exit_code = runSuite(*options); });
}

}  // namespace springcheck
