#pragma once
// The capstan's largest holding load, measured: the load end's mass bisected between the
// holding end's (which holds: a ratio of 1 needs no friction) and twice the closed form's
// holding load (compare/metrics/capstan.h), each trial the scene run whole in one engine and
// judged held when its load end drifted less than kHeld over the run's last half. The answer,
// as the ratio load / hold, against e^(mu phi) and the closed form's holding load.
#include <expected>
#include <string>

#include "compare/engines/engine_registry.h"
#include "compare/metrics/capstan.h"

namespace springcheck {

// A load 1 % past the holding load slips about 4 cm over the last 2 s of a 4 s run (a =
// g (M2 - M1 r) / (M2 + M1 r)); one that holds drifts by its chain's ringing, 1e-5 to 4e-4 m
// (measured on scenes/contact/capstan_*). 1 mm lies between by a factor of ten each way.
inline constexpr double kHeld = 1e-3;  // m
inline constexpr int kBisections = 10;  // the bracket (up to twice the load) to 0.2 %

struct CapstanMeasurement {
  std::string scene, engine;
  Capstan capstan;
  double hold_mass = 0.0;       // kg, the holding end
  double predicted_load = 0.0;  // kg, the closed form's holding load
  double measured_load = 0.0;   // kg, the largest load that held (the bracket's lower end)
  double slipped_load = 0.0;    // kg, the smallest that slipped (the bracket's upper end)
  int runs = 0;
  double error() const { return measured_load / predicted_load - 1.0; }
};

// A capstan scene ready for trials: its model, its capstan (capstanOf), the closed form's
// holding load, and whether a given load holds.
struct CapstanTrials {
  std::string scene;
  mysim::Model model;
  Capstan capstan;
  RunConfig config;
  double predicted_load = 0.0;  // kg

  // Whether the load end holds `load` kg in this engine: the scene run whole, its load end
  // drifting less than kHeld over the run's last half. An engine that refuses the scene or a run
  // that blows up answers with the reason.
  std::expected<bool, std::string> holds(const EngineRegistry& registry, const std::string& engine,
                                         double load) const;
};

// Fails, saying why, on a scene that is not a capstan.
std::expected<CapstanTrials, std::string> capstanTrials(const mysim::Scene& scene);

// The scene must be a capstan (capstanOf); an engine that refuses it or a run that blows up ends
// the measurement with the reason.
std::expected<CapstanMeasurement, std::string> measureCapstan(const EngineRegistry& registry,
                                                              const std::string& engine,
                                                              const mysim::Scene& scene);

}  // namespace springcheck
