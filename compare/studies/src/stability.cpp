#include "compare/studies/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "compare/studies/natural_frequency.h"

namespace springcheck {

mysim::Scene oscillatorScene(double stiffness, double mass, double damping_ratio) {
  mysim::Scene s;
  s.name = "oscillator";
  s.source = "(built-in oscillator)";
  mysim::ParticlesScene& system = s.system.emplace<mysim::ParticlesScene>();
  system.particles = {{mysim::Vec3::Zero(), mysim::Vec3::Zero(), mass, true},
                      {mysim::Vec3(1.1, 0, 0), mysim::Vec3::Zero(), mass, false}};
  system.springs = {{0, 1, 1.0, stiffness, 0.0, mysim::SpringFamily::Custom}};
  s.drag = 2.0 * damping_ratio * std::sqrt(stiffness * mass);
  // The health checks would call a swinging-but-bounded symplectic run "blown up" long before the
  // energy bound below; the bound is this study's criterion, so loosen them.
  s.limits.max_strain = 1e6;
  s.limits.max_energy_ratio = 1e12;
  s.limits.max_energy_rise = std::numeric_limits<double>::infinity();
  s.limits.max_energy_rise_damped = std::numeric_limits<double>::infinity();
  return s;
}

std::optional<double> theoryStableStep(const std::string& integrator, double stiffness, double mass,
                                       double damping_ratio) {
  const mysim::IntegratorInfo* info = mysim::findIntegrator(integrator);
  if (!info) return std::nullopt;
  const std::optional<double> h_omega = info->stable_h_omega(damping_ratio);
  if (!h_omega) return std::nullopt;
  return *h_omega / std::sqrt(stiffness / mass);
}

namespace {

// Bisection in log h between a stable and an unstable step. `stable` may say why a step is not.
StabilityLimit bisect(const std::function<bool(double, std::string&)>& stable_because, double h_min,
                      double h_max, double precision) {
  std::string why, last_why;
  auto stable = [&](double h) {
    why.clear();
    const bool ok = stable_because(h, why);
    if (!ok) last_why = why;
    return ok;
  };
  StabilityLimit limit = [&] {
    StabilityLimit limit;
    if (stable(h_max)) {
      limit.h_stable = h_max;
      limit.status = "stable-at-max";
      return limit;
    }
    // h_min is assumed stable and tried only if every probe above it failed: a run of fixed
    // duration at the smallest step is the dearest probe of all (the oscillator's h w = 1e-3 runs
    // ~3e5 steps, a thousand times a probe near the limit), and a stability that holds at one
    // step holds at every smaller one, so the answer is the one probing it first would give.
    double lo = h_min, hi = h_max;
    while (hi / lo > 1.0 + precision) {
      const double mid = std::sqrt(lo * hi);
      (stable(mid) ? lo : hi) = mid;
    }
    if (lo == h_min && !stable(h_min)) {
      limit.h_unstable = h_min;
      limit.status = "unstable-at-min";
      return limit;
    }
    limit.h_stable = lo;
    limit.h_unstable = hi;
    limit.status = "bracketed";
    return limit;
  }();
  limit.unstable_check = last_why;
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
  auto stable = [&](double h, std::string&) {
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

std::optional<double> stepLimitConstant(const std::string& integrator) {
  const mysim::IntegratorInfo* info = mysim::findIntegrator(integrator);
  if (!info) return std::nullopt;
  const std::optional<double> c = info->stable_h_omega(0.0);
  if (c && *c == 0.0) return std::nullopt;  // unstable at any step without damping
  return c;
}

mysim::Model stressedModel(const mysim::Model& model, double stiffness_scale, double mass_ratio) {
  mysim::Model m = model;
  if (stiffness_scale != 1.0) mysim::scaleStiffness(m, stiffness_scale);
  if (mass_ratio != 1.0 && m.particleCount() > 1) {
    auto heavy = [&](int p) {
      if (m.grid) return (p / m.grid->cols + p % m.grid->cols) % 2 == 1;
      return p % 2 == 1;
    };
    int heavy_count = 0;
    for (int p = 0; p < m.particleCount(); ++p) heavy_count += heavy(p);
    const double light =
        model.mass.sum() / ((m.particleCount() - heavy_count) + mass_ratio * heavy_count);
    for (int p = 0; p < m.particleCount(); ++p) m.mass[p] = heavy(p) ? mass_ratio * light : light;
  }
  return m;
}

double shortestRestLength(const mysim::Model& model) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const mysim::Spring& sp : model.springs) shortest = std::min(shortest, sp.rest_length);
  return model.springs.empty() ? 0.0 : shortest;
}

mysim::Model seededStart(const mysim::Model& model, double amplitude) {
  mysim::Model seeded = model;
  if (amplitude <= 0.0 || model.springs.empty()) return seeded;
  const double shortest = shortestRestLength(model);
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    for (int c = 0; c < 3; ++c) {
      // splitmix64 of the coordinate's index: uniform in [-1, 1).
      std::uint64_t z = 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(3 * p + c + 1);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      z ^= z >> 31;
      const double unit = static_cast<double>(z >> 11) * 0x1.0p-53 * 2.0 - 1.0;
      seeded.start_position[3 * p + c] += amplitude * shortest * unit;
    }
  }
  return seeded;
}

StabilityLimit sceneStability(const EngineRegistry& registry, const mysim::Model& unseeded,
                              const RunConfig& config, const std::string& engine,
                              const SceneStabilitySettings& settings) {
  const mysim::Model model = seededStart(unseeded, settings.seed_amplitude);
  const double w_max = highestFrequency(model);
  const double shortest = shortestRestLength(model);
  // Without a spring mode to scale by, search the scene's own range.
  const double h_min = w_max > 0 ? settings.h_min_omega / w_max : config.run.dt / 100;
  const double h_max = w_max > 0 ? settings.h_max_omega / w_max : config.run.dt * 100;
  std::optional<std::string> refusal;
  auto stable = [&](double h, std::string& why) {
    RunConfig run = config;
    run.run.dt = h;
    const long steps =
        settings.duration > 0 ? std::max(1L, std::lround(settings.duration / h)) : settings.steps;
    run.run.duration = h * static_cast<double>(steps);
    run.run.sample_interval = h * static_cast<double>(std::max(1L, steps / 100));
    run.run.stop_at_solver_failure = true;
    run.run.rest_displacement = settings.rest_of_seed * settings.seed_amplitude * shortest;
    auto record = registry.run(engine, model, run);
    if (!record) {
      why = record.error().message;
      if (record.error().kind != EngineError::Kind::Failed) refusal = why;
      return false;
    }
    if (record->blowup) why = record->blowup->check;
    return !record->blowup;
  };
  StabilityLimit limit = bisect(stable, h_min, h_max, settings.precision);
  if (refusal) {  // the engine cannot run this model at all: no limit to report
    limit = StabilityLimit{};
    limit.status = "refused";
    limit.unstable_check = *refusal;
  }
  limit.system = config.scene_name;
  limit.integrator = engine;
  limit.w_max = w_max;
  limit.mass = model.mass.size() > 0 ? model.mass.maxCoeff() : 0.0;
  limit.stiffness = model.springs.empty() ? 0.0 : model.springs.front().stiffness;
  if (auto c = stepLimitConstant(registry.schemeOf(engine, config.integrator.name)); c && w_max > 0) {
    limit.theory = *c / w_max;
  }
  return limit;
}

}  // namespace springcheck
