#pragma once
// The stability studies' grids: every engine's largest stable step on a scene across stiffness
// and mass ratios (the maps), and every integrator's on the oscillator across stiffness and mass,
// each next to theory, and the tables they are written as (docs/sweeps.md).
#include <expected>
#include <functional>
#include <string>
#include <vector>

#include "compare/studies/stability.h"

namespace springcheck {

// Called as cells finish (from any thread, one at a time): done of total.
using GridProgress = std::function<void(int done, int total)>;

struct StabilityMapSettings {
  std::vector<std::string> engines;     // specs, expanded (EngineRegistry::expand)
  std::vector<int> classic_iterations;  // bullet-classic's passes, each its own map
  std::vector<double> stiffness_scales;  // each spring's stiffness times this (1: as written)
  std::vector<double> mass_ratios;      // heavy / light of neighbouring particles
  SceneStabilitySettings search;
  int jobs = 0;  // jobCount
  GridProgress progress = nullptr;
};

struct StabilityMapCell {
  std::string engine;
  int classic_iterations = 0;  // 0: not bullet-classic
  double stiffness_scale = 1.0, mass_ratio = 1.0;
  StabilityLimit limit;
  // Derived once for every reader: h_stable over theory, and h w_max, where bracketed.
  std::optional<double> ratio, h_w_max;
};

// Every engine's map of one scene (its model stressed per cell, stressedModel).
std::vector<StabilityMapCell> stabilityMaps(const EngineRegistry& registry,
                                            const mysim::Scene& scene,
                                            const StabilityMapSettings& settings);
// out/stability_SCENE.csv
[[nodiscard]] std::expected<void, std::string> writeStabilityMaps(
    const std::string& path, const std::string& scene_name,
    const std::vector<StabilityMapCell>& cells);

struct OscillatorGridSettings {
  std::vector<std::string> integrators;  // canonical names
  std::vector<double> stiffness;         // N/m
  std::vector<double> masses;            // kg
  double damping_ratio = 0.05;
  int jobs = 0;
  GridProgress progress = nullptr;
};
struct OscillatorCell {
  StabilityLimit limit;
  double omega = 0.0;           // sqrt(k / m), rad/s
  std::optional<double> ratio;  // h_stable over a finite, positive theory, where bracketed
};
std::vector<OscillatorCell> oscillatorGrid(const EngineRegistry& registry,
                                           const OscillatorGridSettings& settings);
// out/stability.csv
[[nodiscard]] std::expected<void, std::string> writeOscillatorGrid(
    const std::string& path, const std::vector<OscillatorCell>& cells, double damping_ratio);

}  // namespace springcheck
