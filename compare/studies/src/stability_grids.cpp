#include "compare/studies/stability_grids.h"

#include <cmath>
#include <mutex>
#include <sstream>

#include "compare/io/atomic_file.h"
#include "compare/io/invocation.h"
#include "compare/io/csv.h"
#include "compare/io/text_format.h"
#include "compare/studies/parallel_jobs.h"
#include "mysim/thread_budget.h"

namespace springcheck {
namespace {

std::string cell(const std::optional<double>& v) { return formatNumber(v, 8); }

// Counts finished cells for a progress callback, one report at a time.
class Counter {
 public:
  Counter(int total, GridProgress progress) : total_(total), progress_(std::move(progress)) {}
  void finished() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    if (progress_) progress_(done_, total_);
  }

 private:
  std::mutex mutex_;
  int done_ = 0, total_;
  GridProgress progress_;
};

}  // namespace

std::vector<StabilityMapCell> stabilityMaps(const EngineRegistry& registry,
                                            const mysim::Scene& scene,
                                            const StabilityMapSettings& settings) {
  std::vector<StabilityMapCell> cells;
  for (const std::string& engine : settings.engines) {
    const std::vector<int> passes =
        engine == "bullet-classic" ? settings.classic_iterations : std::vector<int>{0};
    for (int p : passes) {
      for (double scale : settings.stiffness_scales) {
        for (double ratio : settings.mass_ratios)
          cells.push_back({engine, p, scale, ratio, {}, {}, {}});
      }
    }
  }
  const mysim::Model base = mysim::buildModel(scene);
  const RunConfig scene_config = runConfig(scene);
  const int jobs = jobCount(settings.jobs, cells.size());
  Counter counter(static_cast<int>(cells.size()), settings.progress);
  forEachInParallel(cells.size(), jobs, [&](std::size_t k) {
    StabilityMapCell& c = cells[k];
    RunConfig config = scene_config;
    config.run.threads = std::max(1, mysim::availableCores() / jobs);
    // A soft spring may stretch past the strain check under the scene's own load without any
    // numerical trouble: here only the energy checks (runaway, and rise in a passive scene)
    // decide, as in the oscillator study.
    config.limits.max_strain = 1e6;
    if (c.classic_iterations > 0) {
      config.engine_settings["bullet"]["classic_iterations"] = c.classic_iterations;
    }
    c.limit = sceneStability(registry, stressedModel(base, c.stiffness_scale, c.mass_ratio), config,
                             c.engine, settings.search);
    c.limit.mass_ratio = c.mass_ratio;
    const StabilityLimit& l = c.limit;
    if (l.theory && std::isfinite(*l.theory) && l.status == "bracketed") {
      c.ratio = l.h_stable / *l.theory;
    }
    if (l.status == "bracketed") c.h_w_max = l.h_stable * l.w_max;
    counter.finished();
  });
  return cells;
}

std::expected<void, std::string> writeStabilityMaps(const std::string& path,
                                                    const std::string& scene_name,
                                                    const std::vector<StabilityMapCell>& cells) {
  auto written = writeFileAtomically(path, [&](std::ostream& out) {
    out.precision(8);
    out << "system,engine,classic_iterations,stiffness_scale,mass_ratio,w_max,h_stable,h_unstable,"
           "status,unstable_check,theory_h,ratio,h_w_max\n";
    for (const StabilityMapCell& c : cells) {
      const StabilityLimit& l = c.limit;
      out << csvField(scene_name) << ',' << csvField(c.engine) << ','
          << (c.classic_iterations ? std::to_string(c.classic_iterations) : "") << ','
          << c.stiffness_scale << ',' << c.mass_ratio << ',' << l.w_max << ',' << l.h_stable << ','
          << l.h_unstable << ',' << l.status << ',' << csvField(l.unstable_check) << ','
          << cell(l.theory) << ',' << cell(c.ratio) << ',' << cell(c.h_w_max) << '\n';
    }
  });
  if (!written) return written;
  return writeInvocationBeside(path);
}

std::vector<OscillatorCell> oscillatorGrid(const EngineRegistry& registry,
                                           const OscillatorGridSettings& settings) {
  std::vector<OscillatorCell> cells;
  for (const std::string& integrator : settings.integrators) {
    for (double k : settings.stiffness) {
      for (double m : settings.masses) {
        OscillatorCell c;
        c.limit.integrator = integrator;
        c.limit.stiffness = k;
        c.limit.mass = m;
        cells.push_back(c);
      }
    }
  }
  Counter counter(static_cast<int>(cells.size()), settings.progress);
  forEachInParallel(cells.size(), jobCount(settings.jobs, cells.size()), [&](std::size_t k) {
    OscillatorCell& c = cells[k];
    c.limit = oscillatorStability(registry, c.limit.integrator, c.limit.stiffness, c.limit.mass,
                                  settings.damping_ratio, {});
    c.omega = std::sqrt(c.limit.stiffness / c.limit.mass);
    const StabilityLimit& l = c.limit;
    if (l.theory && std::isfinite(*l.theory) && *l.theory > 0 && l.status == "bracketed") {
      c.ratio = l.h_stable / *l.theory;
    }
    counter.finished();
  });
  return cells;
}

std::expected<void, std::string> writeOscillatorGrid(const std::string& path,
                                                     const std::vector<OscillatorCell>& cells,
                                                     double damping_ratio) {
  auto written = writeFileAtomically(path, [&](std::ostream& out) {
    out.precision(8);
    out << "system,integrator,stiffness,mass,omega,damping_ratio,h_stable,h_unstable,status,"
           "theory_h,ratio\n";
    for (const OscillatorCell& c : cells) {
      const StabilityLimit& l = c.limit;
      out << l.system << ',' << l.integrator << ',' << l.stiffness << ',' << l.mass << ','
          << c.omega << ',' << damping_ratio << ',' << l.h_stable << ',' << l.h_unstable << ','
          << l.status << ',' << cell(l.theory) << ',' << cell(c.ratio) << '\n';
    }
  });
  if (!written) return written;
  return writeInvocationBeside(path);
}

}  // namespace springcheck
