#pragma once
// The answer users want from a sweep: the cheapest engine, integrator and step whose error stays
// under a bound, and the runner-up.
#include <expected>
#include <optional>
#include <string>
#include <vector>

#include "compare/studies/sweep_table.h"

namespace springcheck {

// What a choice costs: wall time (the fastest of the sweep's timing rounds; machine-dependent) or
// work (derivative evaluations plus linear or solver iterations: the same on every machine).
enum class Cost { WallTime, Work };

struct Choice {
  std::string engine, integrator, tolerance;  // integrator "-" for engines without one
  // The solver family it stands for: the integrator's catalogue family (mysim: "symplectic",
  // "implicit", "position-based", "local-global", "block-descent", ...), else the engine's name.
  std::string family;
  double dt = 0.0;
  double error = 0.0;  // the sweep's error column (max over frames against its reference), m
  double wall_seconds = 0.0;
  double realtime_factor = 0.0;
  long work = 0;  // derivative evaluations + linear iterations
  std::string reference;
};

// One scene and stiffness of a sweep: the best and the runner-up under the bound (either may be
// missing), and how many rows were considered and met it.
struct Recommendation {
  std::string scene;
  double stiffness_scale = 1.0;
  double max_error = 0.0;
  Cost cost = Cost::WallTime;
  std::optional<Choice> best, runner_up;
  int candidates = 0;  // rows that ran to the end with an error to judge
  int meeting = 0;     // of those, with error <= max_error
  // Each engine's own cheapest choice under the bound (mysim: over all its integrators), the
  // cheapest first: speed at equal accuracy, engine against engine.
  std::vector<Choice> per_engine;
  // Each solver family's cheapest choice under the bound, the cheapest first (which family to
  // use for this cloth at this error).
  std::vector<Choice> per_family;
  // Each family's most accurate finished run, met or not (what a family can reach at all in this
  // sweep), the most accurate first.
  std::vector<Choice> closest_per_family;
};

// The solver family a run stands for: its mysim integrator's catalogue family ("implicit",
// "position-based", ...), else the engine's name.
std::string solverFamily(const std::string& engine, const std::string& integrator);

// Per scene and stiffness scale of the table, in the table's order. Only rows that ran to the
// end ("ok") and carry an error count; the cheapest by `cost` wins, ties to the larger step.
std::vector<Recommendation> recommend(const std::vector<SweepRow>& rows, double max_error,
                                      Cost cost);

// "rk4 in mysim at dt 0.002 s: error 3.1e-05 m, 0.012 s (83x realtime), 4000 evaluations".
std::string describe(const Choice& choice);

}  // namespace springcheck
