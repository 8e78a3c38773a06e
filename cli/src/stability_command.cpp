#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "compare/io/text_format.h"
#include "compare/studies/stability_extremes.h"
#include "compare/studies/stability_grids.h"

namespace springcheck {
namespace {

struct StabilityOptions {
  std::string scene;
  // Scene maps: every engine that steps with a fixed step (dopri5 picks its own), mysim once
  // per fixed-step integrator of the catalogue (EngineRegistry::expand).
  std::vector<std::string> engines = {"all-fixed-step"};
  std::vector<int> classic_iterations = {1, 10, 50};
  std::vector<double> mass_ratios = {1, 100, 1e4};
  long steps = 4000;
  bool whole_run = false;
  double seed_amplitude = 1e-4;  // SceneStabilitySettings::seed_amplitude
  double rest_of_seed = 1e-6;     // SceneStabilitySettings::rest_of_seed
  double max_h_omega = 30.0;     // SceneStabilitySettings::h_max_omega
  std::string name;              // the map's table, stability_NAME.csv (default: the scene's)
  std::vector<std::string> engines_files;
  std::vector<std::string> integrators = mysim::integratorNames(true);
  std::vector<double> stiffness = {10, 100, 1e3, 1e4, 1e5};         // the oscillator's, N/m
  std::vector<double> stiffness_scales = {0.1, 1, 10, 100, 1000};  // a scene's, times as written
  std::vector<double> masses = {1e-6, 1e-2, 1.0};
  double damping_ratio = 0.05;
  std::string out = "out/stability";
  bool extremes = false;
  int jobs = 0;
};

std::string brief(const std::optional<double>& v) { return formatNumber(v, 4); }

// Progress on stderr every tenth of the cells.
GridProgress progressLine(const std::string& what) {
  return [what](int done, int total) {
    if (done % std::max(1, total / 10) == 0 || done == total) {
      std::cerr << what << ": " << done << "/" << total << " done\n";
    }
  };
}

bool makeFolder(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) std::cerr << "error: --out: cannot create " << dir << ": " << ec.message() << '\n';
  return !ec;
}

int report(const std::expected<void, std::string>& written) {
  if (written) return kOk;
  std::cerr << "error: " << written.error() << '\n';
  return kFailure;
}

// Every engine's largest stable step on a scene, across stiffness and mass ratios, next to the
// theory line c / w_max: out/stability_SCENE.csv.
int sceneStabilityMaps(const StabilityOptions& o, const EngineRegistry& registry,
                       const mysim::Scene& scene) {
  StabilityMapSettings settings{registry.expand(o.engines),
                                o.classic_iterations,
                                o.stiffness_scales,
                                o.mass_ratios,
                                {},
                                o.jobs,
                                progressLine("stability " + scene.name)};
  for (const std::string& engine : settings.engines) {
    if (auto ok = registry.check(engine); !ok) {
      std::cerr << "error: --engines: " << ok.error() << '\n';
      return kBadInput;
    }
  }
  settings.search.steps = o.steps;
  settings.search.seed_amplitude = o.seed_amplitude;
  settings.search.rest_of_seed = o.rest_of_seed;
  settings.search.h_max_omega = o.max_h_omega;
  if (o.whole_run) settings.search.duration = scene.duration;
  const std::vector<StabilityMapCell> cells = stabilityMaps(registry, scene, settings);
  std::printf("%-24s %4s %9s %7s %11s %11s %11s %7s %7s  %s\n", "engine", "pass", "k scale",
              "m ratio", "w_max", "h_max [s]", "theory [s]", "h w", "ratio", "status");
  for (const StabilityMapCell& c : cells) {
    const StabilityLimit& l = c.limit;
    std::printf("%-24s %4s %9.3g %7.3g %11.4g %11.4g %11s %7s %7s  %s%s%s\n", c.engine.c_str(),
                c.classic_iterations ? std::to_string(c.classic_iterations).c_str() : "",
                c.stiffness_scale, c.mass_ratio, l.w_max, l.h_stable, brief(l.theory).c_str(),
                brief(c.h_w_max).c_str(), brief(c.ratio).c_str(), l.status.c_str(),
                l.unstable_check.empty() ? "" : ": ", l.unstable_check.substr(0, 60).c_str());
  }
  if (!makeFolder(o.out)) return kFailure;
  const std::string name = o.name.empty() ? scene.name : o.name;
  const std::string path = o.out + "/stability_" + name + ".csv";
  if (report(writeStabilityMaps(path, name, cells)) != kOk) return kFailure;
  std::cout << "results in " << path << '\n';
  return kOk;
}

int stability(const StabilityOptions& o) {
  OscillatorGridSettings settings{
      {}, o.stiffness, o.masses, o.damping_ratio, o.jobs, progressLine("stability")};
  for (const std::string& name : o.integrators) {
    auto canonical = mysim::canonicalIntegratorName(name);
    if (!canonical) {
      std::cerr << "error: --integrators: " << canonical.error() << '\n';
      return kBadInput;
    }
    settings.integrators.push_back(*canonical);
  }
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  if (!o.scene.empty()) {
    auto scene = registry->loadScene(o.scene);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      return kBadInput;
    }
    return sceneStabilityMaps(o, *registry, *scene);
  }
  const std::vector<OscillatorCell> cells = oscillatorGrid(*registry, settings);
  if (!makeFolder(o.out)) return kFailure;
  std::printf("%-12s %-17s %9s %9s %11s %11s %11s %7s\n", "system", "integrator", "k [N/m]",
              "m [kg]", "h_max [s]", "theory [s]", "h w", "ratio");
  for (const OscillatorCell& c : cells) {
    const StabilityLimit& l = c.limit;
    std::printf("%-12s %-17s %9.3g %9.3g %11.4g %11s %11.4g %7s  %s\n", l.system.c_str(),
                l.integrator.c_str(), l.stiffness, l.mass, l.h_stable, brief(l.theory).c_str(),
                l.h_stable * c.omega, brief(c.ratio).c_str(), l.status.c_str());
  }
  if (report(writeOscillatorGrid(o.out + "/stability.csv", cells, o.damping_ratio)) != kOk) {
    return kFailure;
  }
  if (o.extremes && report(writeExtremes(*registry, o.out + "/extremes.csv", o.jobs)) != kOk) {
    return kFailure;
  }
  std::cout << "results in " << o.out << '\n';
  return kOk;
}

// The options of a scene's stability maps (--scene and what shapes its maps).
void addSceneMapOptions(CLI::App* cmd, StabilityOptions& o) {
  cmd->add_option("--scene", o.scene,
                  "Scene: every engine's stability map on it, as written, across "
                  "--stiffness-scales and --mass-ratios, with the w_max theory line (default: the "
                  "built-in oscillator)");
  cmd->add_option("--engines", o.engines, "Scene maps: engines (all-fixed-step: every one; all-direct: all but mysim's iterative families)")
      ->delimiter(',')
      ->capture_default_str();
  addEnginesFileOption(cmd, o.engines_files);
  cmd->add_option("--classic-iterations", o.classic_iterations,
                  "Scene maps: bullet-classic's solver passes, each its own map")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  cmd->add_option("--mass-ratios", o.mass_ratios,
                  "Scene maps: heavy / light mass of neighbouring particles (total mass kept)")
      ->delimiter(',')
      ->check(CLI::Range(1.0, 1e8))
      ->capture_default_str();
  cmd->add_option("--steps", o.steps, "Scene maps: steps per trial run")
      ->check(CLI::Range(10L, 10'000'000L))
      ->capture_default_str();
  cmd->add_option("--seed-amplitude", o.seed_amplitude,
                  "Scene maps: every trial starts with its free particles moved by up to this "
                  "fraction of the shortest rest length (seeded, the same in every engine), so "
                  "a limit does not depend on an engine's round-off; 0 turns it off")
      ->check(CLI::Range(0.0, 1e-2))
      ->capture_default_str();
  cmd->add_option("--rest-of-seed", o.rest_of_seed,
                  "Scene maps: a trial ends early, stable, once no coordinate has moved more "
                  "than this fraction of the seed's displacement over two hundredths of the "
                  "trial in a row (a damped scene at rest only repeats itself); 0, or no seed, "
                  "runs every trial whole")
      ->check(CLI::Range(0.0, 1e-3))
      ->capture_default_str();
  cmd->add_option("--max-h-omega", o.max_h_omega,
                  "Scene maps: the largest step tried, as h w_max (raise it to find where the "
                  "implicit and position-based families stop being stable)")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--name", o.name,
                  "Scene maps: name of the map (its table is stability_NAME.csv; default: the "
                  "scene's name), to keep two maps of one scene apart");
  cmd->add_flag("--whole-run", o.whole_run,
                "Scene maps: every trial runs the scene's whole duration instead of --steps "
                "(a slow instability then shows; costs many steps at small steps)");
}

// The built-in oscillator's grid, and what both forms share (--out, --extremes, --jobs).
void addOscillatorOptions(CLI::App* cmd, StabilityOptions& o) {
  cmd->add_option("--integrators", o.integrators, "Oscillator: integrators")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--stiffness", o.stiffness, "Oscillator: spring stiffness values, N/m")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--stiffness-scales", o.stiffness_scales,
                  "Scene maps: each spring's stiffness as the scene writes it, times these "
                  "(1: as written; the springs' ratios kept)")
      ->delimiter(',')
      ->check(CLI::Range(1e-6, 1e6))
      ->capture_default_str();
  cmd->add_option("--masses", o.masses, "Oscillator: particle masses, kg")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--damping-ratio", o.damping_ratio, "Oscillator damping ratio (drag)")
      ->capture_default_str();
  cmd->add_option("--out", o.out, "Output directory")->capture_default_str();
  cmd->add_flag("--extremes", o.extremes, "Also: 1e6-step energy drift, a 256 x 256 cloth");
  cmd->add_option("--jobs", o.jobs, "Parallel runs (default: all cores)");
}

}  // namespace

void addStabilityCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stability", "Largest stable step per integrator, stiffness and mass (bisection)");
  addSceneMapOptions(cmd, *o);
  addOscillatorOptions(cmd, *o);
  cmd->callback([o, cmd, &exit_code] {
    // A scene is mapped as written: one stiffness for every spring would make another scene
    // (cloth_stiff's 200 N/m flex springs as stiff as its 2000 N/m structural ones).
    if (!o->scene.empty() && cmd->count("--stiffness") > 0) {
      std::cerr << "error: --stiffness sets the oscillator's springs; a scene map scales the "
                   "scene's own springs: use --stiffness-scales\n";
      exit_code = kBadInput;
      return;
    }
    exit_code = stability(*o);
  });
}

}  // namespace springcheck
