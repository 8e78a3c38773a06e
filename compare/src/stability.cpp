#include "compare/stability.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>


namespace springcheck {

mysim::Scene oscillatorScene(double stiffness, double mass, double damping_ratio) {
  mysim::Scene s;
  s.name = "oscillator";
  s.source = "(built-in oscillator)";
  s.kind = mysim::SystemKind::Particles;
  s.particles = {{mysim::Vec3::Zero(), mysim::Vec3::Zero(), mass, true},
                 {mysim::Vec3(1.1, 0, 0), mysim::Vec3::Zero(), mass, false}};
  s.springs = {{0, 1, 1.0, stiffness, 0.0, mysim::SpringFamily::Custom}};
  s.drag = 2.0 * damping_ratio * std::sqrt(stiffness * mass);
  // The health checks would call a swinging-but-bounded symplectic run "blown up" long before the
  // energy bound below; the bound is this study's criterion, so loosen them.
  s.limits.max_strain = 1e6;
  s.limits.max_energy_ratio = 1e12;
  s.limits.max_energy_rise = std::numeric_limits<double>::infinity();
  return s;
}

std::optional<double> theoryStableStep(const std::string& integrator, double stiffness, double mass,
                                       double damping_ratio) {
  const double w = std::sqrt(stiffness / mass);
  if (integrator == "symplectic-euler" || integrator == "verlet") return 2.0 / w;
  if (integrator == "rk4") return 2.0 * std::sqrt(2.0) / w;
  if (integrator == "euler") return 2.0 * damping_ratio / w;
  if (integrator == "backward-euler") return std::numeric_limits<double>::infinity();
  return std::nullopt;
}

namespace {

// Bisection in log h between a stable and an unstable step.
StabilityLimit bisect(const std::function<bool(double)>& stable, double h_min, double h_max,
                      double precision) {
  StabilityLimit limit;
  if (stable(h_max)) {
    limit.h_stable = h_max;
    limit.status = "stable-at-max";
    return limit;
  }
  if (!stable(h_min)) {
    limit.h_unstable = h_min;
    limit.status = "unstable-at-min";
    return limit;
  }
  double lo = h_min, hi = h_max;
  while (hi / lo > 1.0 + precision) {
    const double mid = std::sqrt(lo * hi);
    (stable(mid) ? lo : hi) = mid;
  }
  limit.h_stable = lo;
  limit.h_unstable = hi;
  limit.status = "bracketed";
  return limit;
}

}  // namespace

StabilityLimit oscillatorStability(const EngineRegistry& registry, const std::string& integrator,
                                   double stiffness, double mass, double damping_ratio,
                                   const StabilitySettings& settings) {
  const double w = std::sqrt(stiffness / mass);
  const mysim::Scene scene = oscillatorScene(stiffness, mass, damping_ratio);
  const mysim::Model model = mysim::buildModel(scene);
  RunConfig config = runConfig(scene);
  config.integrator.name = integrator;
  config.integrator.cg_tolerance = 1e-12;
  auto stable = [&](double h) {
    RunConfig run = config;
    run.run.dt = h;
    run.run.duration = h * std::max(200.0, std::ceil(settings.periods * 2 * M_PI / (w * h)));
    auto record = registry.run("mysim", model, run);
    if (!record || record->blowup) return false;
    const double e0 = record->energies.front().total();
    for (const mysim::EnergyTerms& e : record->energies) {
      if (!(e.total() <= settings.energy_bound * e0)) return false;  // NaN counts as unstable
    }
    return true;
  };
  StabilityLimit limit =
      bisect(stable, settings.h_min_omega / w, settings.h_max_omega / w, settings.precision);
  limit.system = "oscillator";
  limit.integrator = integrator;
  limit.stiffness = stiffness;
  limit.mass = mass;
  limit.theory = theoryStableStep(integrator, stiffness, mass, damping_ratio);
  return limit;
}

StabilityLimit sceneStability(const EngineRegistry& registry, const mysim::Model& model,
                              const RunConfig& config, const std::string& integrator,
                              double stiffness, double mass, double h_min, double h_max,
                              double precision) {
  mysim::Model base = model;
  for (mysim::Spring& s : base.springs) s.stiffness = stiffness;
  if (mass > 0) base.mass.setConstant(mass);
  RunConfig run = config;
  run.integrator.name = integrator;
  auto stable = [&](double h) {
    run.run.dt = h;
    auto record = registry.run("mysim", base, run);
    return record && !record->blowup;
  };
  StabilityLimit limit = bisect(stable, h_min, h_max, precision);
  limit.system = config.scene_name;
  limit.integrator = integrator;
  limit.stiffness = stiffness;
  limit.mass = base.mass.size() > 0 ? base.mass.maxCoeff() : 0.0;
  return limit;
}

}  // namespace springcheck
