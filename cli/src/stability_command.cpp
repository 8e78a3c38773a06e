#include <sys/resource.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

#include "commands.h"
#include "compare/io/atomic_file.h"
#include "compare/io/csv.h"
#include "compare/metrics/energy_metric.h"
#include "compare/studies/stability.h"
#include "mysim/thread_budget.h"

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
  std::vector<std::string> engines_files;
  std::vector<std::string> integrators = mysim::integratorNames(true);
  std::vector<double> stiffness = {10, 100, 1e3, 1e4, 1e5};
  std::vector<double> masses = {1e-6, 1e-2, 1.0};
  double damping_ratio = 0.05;
  std::string out = "out/stability";
  bool extremes = false;
  int jobs = 0;
};

std::string cell(const std::optional<double>& v) {
  if (!v) return "";
  std::ostringstream s;
  s.precision(8);
  s << *v;
  return s.str();
}

// Runs f(k) for k in [0, n) over `jobs` threads.
void parallelFor(int n, int jobs, const std::function<void(int)>& f) {
  std::atomic<int> next{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < jobs; ++t) {
    threads.emplace_back([&] {
      for (int k; (k = next++) < n;) f(k);
    });
  }
  for (std::thread& t : threads) t.join();
}

// Very long runs, very small masses, a very large cloth: what happens at the extremes.
std::expected<void, std::string> writeExtremes(const EngineRegistry& registry,
                                               const std::string& path, int jobs) {
  std::ostringstream out;
  out.precision(8);
  out << "case,integrator,quantity,value,unit\n";
  // 10^6 steps of the undamped oscillator at h w = 0.1.
  const std::vector<std::string> long_methods = {"symplectic-euler", "verlet", "rk4",
                                                 "backward-euler", "trapezoidal"};
  std::vector<std::string> rows(long_methods.size());
  parallelFor(static_cast<int>(long_methods.size()), jobs, [&](int k) {
    mysim::Scene s = oscillatorScene(100.0, 1.0, 0.0);
    s.integrator.name = long_methods[k];
    s.integrator.cg_tolerance = 1e-12;
    s.dt = 0.01;
    s.duration = 1e6 * s.dt;
    s.sample_interval = s.duration / 1000;
    auto r = registry.run("mysim", s);
    const EnergyDrift d = energyDrift(r->energies);
    std::ostringstream row;
    row.precision(8);
    row << "oscillator 1e6 steps h w = 0.1," << long_methods[k] << ",energy drift max,"
        << d.max_abs_total << ",rel\n"
        << "oscillator 1e6 steps h w = 0.1," << long_methods[k] << ",energy drift end,"
        << d.total.back() << ",rel\n"
        << "oscillator 1e6 steps h w = 0.1," << long_methods[k] << ",wall time," << r->wall_seconds
        << ",s\n";
    rows[k] = row.str();
  });
  for (const std::string& row : rows) out << row;

  // A 256 x 256 cloth (the matched hanging cloth's 1 m, 0.5 kg and springs at 65 536 particles).
  for (auto [integrator, dt, steps] :
       {std::tuple{"symplectic-euler", 1e-4, 50}, {"backward-euler", 2e-3, 5}}) {
    mysim::Scene s;
    s.name = "cloth256";
    s.kind = mysim::SystemKind::Cloth;
    s.cloth.rows = s.cloth.cols = 256;
    s.cloth.particle_mass = 0.5 / (256.0 * 256.0);
    s.cloth.structural = s.cloth.shear = mysim::SpringParameters{100.0, 0.0};
    s.cloth.flex = mysim::SpringParameters{10.0, 0.0};
    s.pins = {0, 255};
    s.gravity = mysim::Vec3(0, -9.8, 0);
    s.integrator.name = integrator;
    s.integrator.cg_tolerance = 1e-6;
    s.dt = dt;
    s.duration = steps * dt;
    s.sample_interval = s.duration;
    auto r = registry.run("mysim", s);
    out << "cloth 256 x 256," << integrator << ",time per step," << r->wall_seconds / r->steps
        << ",s\n"
        << "cloth 256 x 256," << integrator << ",stable (1 yes 0 no)," << (r->blowup ? 0 : 1)
        << ",\n";
    if (r->counts.linear_iterations) {
      out << "cloth 256 x 256," << integrator << ",CG iterations per step,"
          << double(r->counts.linear_iterations) / r->steps << ",\n";
    }
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  out << "process,all,peak resident memory," << usage.ru_maxrss / 1024.0 << ",MiB\n";
  return writeFileAtomically(path, [&](std::ostream& file) { file << out.str(); });
}

// Every engine's largest stable step on a scene, across stiffness and mass ratios, next to the
// theory line c / w_max: out/stability_SCENE.csv.
int sceneStabilityMaps(const StabilityOptions& o, const EngineRegistry& registry,
                       const mysim::Scene& scene, int jobs) {
  const std::vector<std::string> engines = registry.expand(o.engines);
  for (const std::string& engine : engines) {
    if (auto ok = registry.check(engine); !ok) {
      std::cerr << "error: --engines: " << ok.error() << '\n';
      return kBadInput;
    }
  }
  struct Cell {
    std::string engine;
    int classic_iterations;  // 0: not bullet-classic
    double k, ratio;
  };
  std::vector<Cell> cells;
  for (const std::string& engine : engines) {
    const std::vector<int> passes =
        engine == "bullet-classic" ? o.classic_iterations : std::vector<int>{0};
    for (int p : passes) {
      for (double k : o.stiffness) {
        for (double ratio : o.mass_ratios) cells.push_back({engine, p, k, ratio});
      }
    }
  }
  const mysim::Model base = mysim::buildModel(scene);
  std::vector<StabilityLimit> limits(cells.size());
  std::mutex mutex;
  int done = 0;
  SceneStabilitySettings settings;
  settings.steps = o.steps;
  if (o.whole_run) settings.duration = scene.duration;
  parallelFor(static_cast<int>(cells.size()), jobs, [&](int k) {
    const Cell& c = cells[k];
    RunConfig config = runConfig(scene);
    config.run.threads = std::max(1, mysim::availableCores() / jobs);
    // A soft spring may stretch past the strain check under the scene's own load without any
    // numerical trouble: here only the energy checks (runaway, and rise in a passive scene)
    // decide, as in the oscillator study.
    config.limits.max_strain = 1e6;
    if (c.classic_iterations > 0) {
      config.engine_settings["bullet"]["classic_iterations"] = c.classic_iterations;
    }
    limits[k] =
        sceneStability(registry, stressedModel(base, c.k, c.ratio), config, c.engine, settings);
    limits[k].mass_ratio = c.ratio;
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (done % std::max<int>(1, cells.size() / 10) == 0 || done == static_cast<int>(cells.size())) {
      std::cerr << "stability " << scene.name << ": " << done << "/" << cells.size() << " done\n";
    }
  });
  std::ostringstream out;
  out.precision(8);
  out << "system,engine,classic_iterations,stiffness,mass_ratio,w_max,h_stable,h_unstable,status,"
         "unstable_check,theory_h,ratio,h_w_max\n";
  auto brief = [](const std::optional<double>& v) {
    char text[32] = "";
    if (v) std::snprintf(text, sizeof text, "%.4g", *v);
    return std::string(text);
  };
  std::printf("%-24s %4s %9s %7s %11s %11s %11s %7s %7s  %s\n", "engine", "pass", "k [N/m]",
              "m ratio", "w_max", "h_max [s]", "theory [s]", "h w", "ratio", "status");
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const StabilityLimit& l = limits[k];
    std::optional<double> ratio;
    if (l.theory && std::isfinite(*l.theory) && l.status == "bracketed") {
      ratio = l.h_stable / *l.theory;
    }
    const std::optional<double> hw =
        l.status == "bracketed" ? std::optional(l.h_stable * l.w_max) : std::nullopt;
    out << csvField(scene.name) << ',' << csvField(cells[k].engine) << ','
        << (cells[k].classic_iterations ? std::to_string(cells[k].classic_iterations) : "") << ','
        << cells[k].k << ',' << cells[k].ratio << ',' << l.w_max << ',' << l.h_stable << ','
        << l.h_unstable << ',' << l.status << ',' << csvField(l.unstable_check) << ','
        << cell(l.theory) << ',' << cell(ratio) << ',' << cell(hw) << '\n';
    std::printf(
        "%-24s %4s %9.3g %7.3g %11.4g %11.4g %11s %7s %7s  %s%s%s\n", cells[k].engine.c_str(),
        cells[k].classic_iterations ? std::to_string(cells[k].classic_iterations).c_str() : "",
        cells[k].k, cells[k].ratio, l.w_max, l.h_stable, brief(l.theory).c_str(), brief(hw).c_str(),
        brief(ratio).c_str(), l.status.c_str(), l.unstable_check.empty() ? "" : ": ",
        l.unstable_check.substr(0, 60).c_str());
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) {
    std::cerr << "error: --out: cannot create " << o.out << ": " << ec.message() << '\n';
    return kFailure;
  }
  const std::string path = o.out + "/stability_" + scene.name + ".csv";
  if (auto written = writeFileAtomically(path, [&](std::ostream& file) { file << out.str(); });
      !written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  std::cout << "results in " << path << '\n';
  return kOk;
}

int stability(const StabilityOptions& o) {
  const int jobs =
      o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (const std::string& name : o.integrators) {
    if (auto ok = mysim::canonicalIntegratorName(name); !ok) {
      std::cerr << "error: --integrators: " << ok.error() << '\n';
      return kBadInput;
    }
  }
  const std::optional<EngineRegistry> registry = makeRegistry(o.engines_files);
  if (!registry) return kBadInput;
  if (!o.scene.empty()) {
    auto scene = registry->loadScene(o.scene);
    if (!scene) {
      std::cerr << "error: " << scene.error() << '\n';
      return kBadInput;
    }
    return sceneStabilityMaps(o, *registry, *scene, jobs);
  }
  struct Combo {
    std::string integrator;
    double k, m;
  };
  std::vector<Combo> combos;
  for (const std::string& i : o.integrators) {
    for (double k : o.stiffness) {
      for (double m : o.masses) combos.push_back({*mysim::canonicalIntegratorName(i), k, m});
    }
  }
  std::vector<StabilityLimit> limits(combos.size());
  std::mutex mutex;
  int done = 0;
  parallelFor(static_cast<int>(combos.size()), jobs, [&](int k) {
    const Combo& c = combos[k];
    limits[k] = oscillatorStability(*registry, c.integrator, c.k, c.m, o.damping_ratio, {});
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (done % std::max<int>(1, combos.size() / 10) == 0 ||
        done == static_cast<int>(combos.size())) {
      std::cerr << "stability: " << done << "/" << combos.size() << " done\n";
    }
  });
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) {
    std::cerr << "error: --out: cannot create " << o.out << ": " << ec.message() << '\n';
    return kFailure;
  }
  std::ostringstream out;
  out.precision(8);
  out << "system,integrator,stiffness,mass,omega,damping_ratio,h_stable,h_unstable,status,theory_h,"
         "ratio\n";
  std::printf("%-12s %-17s %9s %9s %11s %11s %11s %7s\n", "system", "integrator", "k [N/m]",
              "m [kg]", "h_max [s]", "theory [s]", "h w", "ratio");
  for (const StabilityLimit& l : limits) {
    const double w = std::sqrt(l.stiffness / l.mass);
    std::optional<double> ratio;
    if (l.theory && std::isfinite(*l.theory) && *l.theory > 0 && l.status == "bracketed") {
      ratio = l.h_stable / *l.theory;
    }
    out << l.system << ',' << l.integrator << ',' << l.stiffness << ',' << l.mass << ',' << w << ','
        << o.damping_ratio << ',' << l.h_stable << ',' << l.h_unstable << ',' << l.status << ','
        << cell(l.theory) << ',' << cell(ratio) << '\n';
    std::printf("%-12s %-17s %9.3g %9.3g %11.4g %11s %11.4g %7s  %s\n", l.system.c_str(),
                l.integrator.c_str(), l.stiffness, l.mass, l.h_stable, cell(l.theory).c_str(),
                l.h_stable * w, cell(ratio).substr(0, 6).c_str(), l.status.c_str());
  }
  if (auto written = writeFileAtomically(o.out + "/stability.csv",
                                         [&](std::ostream& file) { file << out.str(); });
      !written) {
    std::cerr << "error: " << written.error() << '\n';
    return kFailure;
  }
  if (o.extremes) {
    if (auto written = writeExtremes(*registry, o.out + "/extremes.csv", jobs); !written) {
      std::cerr << "error: " << written.error() << '\n';
      return kFailure;
    }
  }
  std::cout << "results in " << o.out << '\n';
  return kOk;
}

}  // namespace

void addStabilityCommand(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stability", "Largest stable step per integrator, stiffness and mass (bisection)");
  cmd->add_option("--scene", o->scene,
                  "Scene: every engine's stability map on it across --stiffness and "
                  "--mass-ratios, with the w_max theory line (default: the built-in oscillator)");
  cmd->add_option("--engines", o->engines, "Scene maps: engines (all-fixed-step: every one)")
      ->delimiter(',')
      ->capture_default_str();
  addEnginesFileOption(cmd, o->engines_files);
  cmd->add_option("--classic-iterations", o->classic_iterations,
                  "Scene maps: bullet-classic's solver passes, each its own map")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  cmd->add_option("--mass-ratios", o->mass_ratios,
                  "Scene maps: heavy / light mass of neighbouring particles (total mass kept)")
      ->delimiter(',')
      ->check(CLI::Range(1.0, 1e8))
      ->capture_default_str();
  cmd->add_option("--steps", o->steps, "Scene maps: steps per trial run")
      ->check(CLI::Range(10L, 10'000'000L))
      ->capture_default_str();
  cmd->add_flag("--whole-run", o->whole_run,
                "Scene maps: every trial runs the scene's whole duration instead of --steps "
                "(a slow instability then shows; costs many steps at small steps)");
  cmd->add_option("--integrators", o->integrators, "Oscillator: integrators")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--stiffness", o->stiffness, "Spring stiffness values, N/m")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--masses", o->masses, "Oscillator: particle masses, kg")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--damping-ratio", o->damping_ratio, "Oscillator damping ratio (drag)")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output directory")->capture_default_str();
  cmd->add_flag("--extremes", o->extremes, "Also: 1e6-step energy drift, a 256 x 256 cloth");
  cmd->add_option("--jobs", o->jobs, "Parallel runs (default: all cores)");
  cmd->callback([o, &exit_code] { exit_code = stability(*o); });
}

}  // namespace springcheck
