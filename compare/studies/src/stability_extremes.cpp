#include "compare/studies/stability_extremes.h"

#include <sys/resource.h>

#include <mutex>
#include <sstream>
#include <tuple>

#include "compare/io/atomic_file.h"
#include "compare/metrics/energy_metric.h"
#include "compare/studies/parallel_jobs.h"
#include "compare/studies/stability.h"

namespace springcheck {

namespace {

// 10^6 steps of the undamped oscillator at h w = 0.1, each long-run method's energy drift and
// wall time as rows of the extremes table.
std::expected<std::string, std::string> longOscillatorRows(const EngineRegistry& registry,
                                                           int jobs) {
  const std::vector<std::string> long_methods = {"symplectic-euler", "verlet", "rk4",
                                                 "backward-euler", "trapezoidal"};
  std::string failed;  // the first run that could not be made, if any
  std::vector<std::string> rows(long_methods.size());
  std::mutex mutex;
  forEachInParallel(long_methods.size(), jobCount(jobs, long_methods.size()), [&](std::size_t k) {
    mysim::Scene s = oscillatorScene(100.0, 1.0, 0.0);
    s.integrator.name = long_methods[k];
    s.integrator.cg_tolerance = 1e-12;
    s.dt = 0.01;
    s.duration = 1e6 * s.dt;
    s.sample_interval = s.duration / 1000;
    auto r = registry.run("mysim", s);
    if (!r) {
      std::lock_guard<std::mutex> lock(mutex);
      failed = long_methods[k] + ": " + r.error().message;
      return;
    }
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
  if (!failed.empty()) return std::unexpected("oscillator 1e6 steps, " + failed);
  std::string text;
  for (const std::string& row : rows) text += row;
  return text;
}

// The matched hanging cloth's 1 m, 0.5 kg and springs at 256 x 256 (65 536 particles).
mysim::Scene largeCloth(const char* integrator, double dt, int steps) {
  mysim::Scene s;
  s.name = "cloth256";
  mysim::ClothScene& cloth = s.system.emplace<mysim::ClothScene>();
  cloth.shape.rows = cloth.shape.cols = 256;
  cloth.shape.particle_mass = 0.5 / (256.0 * 256.0);
  cloth.shape.structural = cloth.shape.shear = mysim::SpringParameters{100.0, 0.0};
  cloth.shape.flex = mysim::SpringParameters{10.0, 0.0};
  cloth.start.pins = {0, 255};
  s.gravity = mysim::Vec3(0, -9.8, 0);
  s.integrator.name = integrator;
  s.integrator.cg_tolerance = 1e-6;
  s.dt = dt;
  s.duration = steps * dt;
  s.sample_interval = s.duration;
  return s;
}

}  // namespace

// Very long runs, a very large cloth: what happens at the extremes.
std::expected<void, std::string> writeExtremes(const EngineRegistry& registry,
                                               const std::string& path, int jobs) {
  std::ostringstream out;
  out.precision(8);
  out << "case,integrator,quantity,value,unit\n";
  auto long_rows = longOscillatorRows(registry, jobs);
  if (!long_rows) return std::unexpected(long_rows.error());
  out << *long_rows;
  for (auto [integrator, dt, steps] :
       {std::tuple{"symplectic-euler", 1e-4, 50}, {"backward-euler", 2e-3, 5}}) {
    auto r = registry.run("mysim", largeCloth(integrator, dt, steps));
    if (!r)
      return std::unexpected(std::string("cloth 256 x 256, ") + integrator + ": " +
                             r.error().message);
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

}  // namespace springcheck
