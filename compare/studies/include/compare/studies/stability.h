#pragma once
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "mysim/scene.h"

namespace springcheck {

// The test oscillator: a particle of mass m on a spring of stiffness k to a pinned anchor,
// displaced 10 % of the 1 m rest length, with drag c = 2 zeta sqrt(k m).
mysim::Scene oscillatorScene(double stiffness, double mass, double damping_ratio);

// Theory for the largest stable step on that oscillator (w = sqrt(k / m)): the catalogue's
// stable_h_omega at the damping ratio, over w (mysim/integrator.h derives each).
std::optional<double> theoryStableStep(const std::string& integrator, double stiffness, double mass,
                                       double damping_ratio);

struct StabilityLimit {
  std::string system;          // "oscillator" or the scene's name
  std::string integrator;      // the oscillator's; on a scene, the engine spec ("mysim:rk4", ...)
  double mass_ratio = 1.0;     // scenes: heavy / light neighbour
  double w_max = 0.0;          // rad/s, highest natural frequency (natural_frequency.h)
  std::string unstable_check;  // the health check the smallest unstable step failed
  double stiffness = 0.0;      // N/m
  double mass = 0.0;           // kg
  double h_stable = 0.0;       // largest step found stable, s
  double h_unstable = 0.0;     // smallest step found unstable (0 if none up to the range's top), s
  std::string status;          // "bracketed", "stable-at-max", "unstable-at-min"
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
                                   double stiffness, double mass, double damping_ratio,
                                   const StabilitySettings& settings);

// The constant c of an integrator's stability limit h w_max < c on an undamped linear system,
// from the catalogue, where theory gives one (an engine's through EngineRegistry::schemeOf);
// none where the method is unstable at any step without damping (forward Euler, Heun) or adapts
// its step (dopri5).
std::optional<double> stepLimitConstant(const std::string& integrator);

// The model as written with every spring's stiffness times `stiffness_scale` (their ratios kept:
// a cloth's flex springs stay a tenth of its structural ones) and neighbouring particles' masses
// in the ratio `mass_ratio` (heavy / light, alternating along the index, in a checkerboard on a
// cloth grid; the total mass kept): light and heavy particles mixed, a classic stressor.
mysim::Model stressedModel(const mysim::Model& model, double stiffness_scale, double mass_ratio);

struct SceneStabilitySettings {
  long steps = 4000;  // each trial runs this many steps (instability grows per step)
  // > 0: each trial runs this long instead (s), whatever its step: a step called stable then
  // holds over the whole run, at the price of many steps at small h.
  double duration = 0.0;
  double h_min_omega = 1e-2;  // search range, as h w_max
  double h_max_omega = 30.0;
  double precision = 0.02;  // stop when h_unstable / h_stable < 1 + precision
  // Every trial starts from the scene's state with each free particle moved by up to this
  // fraction of the shortest spring's rest length per coordinate (seededStart): the unstable
  // modes start at that amplitude in every engine, not at the engine's round-off (0: off).
  double seed_amplitude = 1e-4;
  // A trial ends early, stable, once it has come to rest: no coordinate moved more than this
  // fraction of the seed's displacement (seed_amplitude of the shortest rest length) over each of
  // two sampling intervals (a hundredth of the trial each) in a row (RunSettings::
  // rest_displacement). Why it cannot hide a growing mode: the seed gives every mode a share of
  // its order, below which a growing mode never falls; one that moved under 1e-6 of it in an
  // interval grew by under 1e-6 of itself there, under 1e-4 over the whole trial. Without a seed
  // (seed_amplitude 0) a trial may start at rest, unstable or not: every trial then runs whole.
  // Measured on the main job's cloth maps: the same tables with and without, in 8 % and 20 %
  // fewer steps and a third less time (the implicit engines' stable probes at large steps rest
  // after a few hundred of their 4000 steps). 0: every trial runs its full length.
  double rest_of_seed = 1e-6;
};

// The model with its free particles' start positions perturbed by up to `amplitude` times the
// shortest rest length per coordinate, from a counter hash of the particle and coordinate: the
// same numbers for every engine and run. Why: just above a step limit the growing mode grows by a
// factor close to 1 a step; started from round-off it needs ~ln(1e16) / ln(growth) steps to show
// in double precision but ~ln(1e7) / ln(growth) in float, so an unseeded search measures the
// precision (float steppers failed at 0.66-0.80 of mysim's limit for the same method). Seeded at
// 1e-4 of a rest length (a strain of 1e-4, far above either round-off and far below anything
// nonlinear), the limit is the method's and the step's.
mysim::Model seededStart(const mysim::Model& model, double amplitude);

// The shortest spring's rest length, m (0 without springs): the scale of the seed and of rest.
double shortestRestLength(const mysim::Model& model);

// Largest stable step of one engine on a (stressed) model by bisection in log h; stable = no
// health check fails (blow-up, strain, energy, energy rise in a passive scene, step limit).
StabilityLimit sceneStability(const EngineRegistry& registry, const mysim::Model& model,
                              const RunConfig& config, const std::string& engine,
                              const SceneStabilitySettings& settings);

}  // namespace springcheck
