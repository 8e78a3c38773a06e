#pragma once
// A sweep's specification: the grid of scenes, engines, integrators, steps, stiffness scales
// and tolerances, read once (every scene parsed once), and the cases it expands to.
#include <expected>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "compare/studies/sweep_table.h"
#include "mysim/scene.h"

namespace springcheck {

// A grid of runs: scenes x engines (x integrators for mysim) x steps x stiffness scales.
// Schema in docs/sweeps.md.
struct SweepSpec {
  std::string source;
  std::string name;
  std::vector<std::string> scenes;              // paths, resolved against the spec's directory
  std::map<std::string, mysim::Scene> loaded;   // each scene, read and validated once
  std::vector<std::string> engines;             // registry engines (mysim, Bullet, the user's)
  std::vector<std::string> integrators;         // for the engines that take one (mysim)
  std::vector<std::string> integrator_engines;  // those of `engines` that take an integrator
  std::string engines_file;                     // the user's engines the spec names, if any
  std::vector<double> dts;                      // s
  std::vector<double> stiffness_scales{1.0};    // every spring's stiffness times this
  // Adaptive integrators (dopri5): abs and rel tolerance, an axis of its own (empty: the scene's).
  std::vector<double> tolerances;
  std::optional<double> duration;  // s, overrides the scenes'
  double sample_interval = 0.0;    // s, a multiple of every dt: frames line up
  // The reference every row is measured against: the scene's closed form, or a converged run
  // (`reference_integrator` at the smallest dt / `reference_refine`), or with reference_self each
  // case's own engine, integrator and tolerance at that step (self-consistency, Erez et al. 2015:
  // every engine's convergence measured against itself).
  bool reference_closed_form = false;
  bool reference_self = false;
  std::string reference_integrator = "rk4";
  int reference_refine = 16;
};

// An `engines_file` the spec names (relative to the spec) is added to `registry`.
[[nodiscard]] std::expected<SweepSpec, std::string> loadSweepSpec(const std::string& path,
                                                                  EngineRegistry& registry);
// The same from text; `source` names it and places it (scene paths resolve against its folder).
[[nodiscard]] std::expected<SweepSpec, std::string> parseSweepSpec(const std::string& text,
                                                                   const std::string& source,
                                                                   EngineRegistry& registry);

std::vector<SweepCase> expandSweep(const SweepSpec& spec);

// The sweep recommend runs on a scene (read from `path`): every engine and fixed-step integrator
// of the catalogue at 4, 2, 1, 1/2 and 1/4 times the scene's dt, sampled every 4 dt, against RK4
// at a step 16 times finer than the finest.
SweepSpec sweepAroundScene(const EngineRegistry& registry, const std::string& path,
                           mysim::Scene scene);

// What a case runs: its model with the case's stiffness scale, and the run config with the
// case's integrator and step and the spec's duration and sampling (built once per case; its
// timing repeats reuse it).
struct CaseRun {
  mysim::Model model;
  RunConfig config;
};
[[nodiscard]] std::expected<CaseRun, std::string> caseRun(const SweepSpec& spec,
                                                          const SweepCase& c);

}  // namespace springcheck
