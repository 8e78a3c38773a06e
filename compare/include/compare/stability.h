#pragma once
#include <optional>
#include <string>
#include <vector>

#include "compare/engine_registry.h"
#include "mysim/scene.h"

namespace springcheck {

// The test oscillator: a particle of mass m on a spring of stiffness k to a pinned anchor,
// displaced 10 % of the 1 m rest length, with drag c = 2 zeta sqrt(k m).
mysim::Scene oscillatorScene(double stiffness, double mass, double damping_ratio);

// Theory for the largest stable step on that oscillator (w = sqrt(k / m)), from each method's
// amplification factor on y' = lambda y, lambda = -zeta w +- i w sqrt(1 - zeta^2):
//   symplectic Euler, Verlet: h w < 2 (undamped);  RK4: h w <= 2 sqrt(2) (undamped);
//   forward Euler: |1 + h lambda| <= 1 <=> h <= 2 zeta / w = c / k;
//   backward Euler: any h (infinity);  trapezoidal (Heun) and dopri5: no finite line (none).
std::optional<double> theoryStableStep(const std::string& integrator, double stiffness, double mass,
                                       double damping_ratio);

struct StabilityLimit {
  std::string system;  // "oscillator" or the scene's name
  std::string integrator;
  double stiffness = 0.0;   // N/m
  double mass = 0.0;        // kg
  double h_stable = 0.0;    // largest step found stable, s
  double h_unstable = 0.0;  // smallest step found unstable (0 if none up to the range's top), s
  std::string status;       // "bracketed", "stable-at-max", "unstable-at-min"
  std::optional<double> theory;  // s
};

struct StabilitySettings {
  double periods = 50;         // oscillator run length, in periods (at least 200 steps)
  double energy_bound = 10.0;  // stable: total energy never above this many times its start
  double h_min_omega = 1e-3;   // search range, as h w
  double h_max_omega = 100.0;
  double precision = 0.01;  // stop when h_unstable / h_stable < 1 + precision
};

// Largest stable step by bisection (in log h) for one integrator on the oscillator.
StabilityLimit oscillatorStability(const EngineRegistry& registry, const std::string& integrator,
                                   double stiffness, double mass,
                                   double damping_ratio, const StabilitySettings& settings);

// The same on a model whose springs all get `stiffness` and particles `mass` (0: keep the
// model's), over the run's duration; stable = no blow-up (the run's health checks).
StabilityLimit sceneStability(const EngineRegistry& registry, const mysim::Model& model,
                              const RunConfig& config, const std::string& integrator,
                              double stiffness, double mass, double h_min, double h_max,
                              double precision);

}  // namespace springcheck
