#pragma once
#include <expected>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/engines/engine_registry.h"
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

// One run of the grid. `id` is its place in the full grid (stable across shards and resumes).
struct SweepCase {
  int id = 0;
  std::string scene;
  std::string engine;
  std::string integrator;  // mysim's; the Bullet engines' own scheme otherwise
  double dt = 0.0;
  double stiffness_scale = 1.0;
  double tolerance = 0.0;  // adaptive integrators: abs and rel tolerance (0: the scene's)
};
std::vector<SweepCase> expandSweep(const SweepSpec& spec);

// What a case runs: the scene file (for its name and metrics), its model with the case's
// stiffness scale, and the run config with the case's integrator and step and the spec's
// duration and sampling.
struct CaseRun {
  mysim::Scene scene;
  mysim::Model model;
  RunConfig config;
};
[[nodiscard]] std::expected<CaseRun, std::string> caseRun(const SweepSpec& spec,
                                                          const SweepCase& c);

// Results table: one row per case, in this column order.
const std::vector<std::string>& sweepColumns();
using SweepRow = std::vector<std::string>;  // values in sweepColumns() order
// A column's place in a row (sweepColumns().size() for a name that is none).
std::size_t sweepColumn(std::string_view name);

struct SweepOptions {
  int jobs = 1;
  // Timing (docs/timing.md). The cases run `jobs` at a time for their results; with repeats > 1
  // they are then timed one at a time (cases run side by side slow each other down through the
  // caches and memory they share: up to 1.8x on a 2-core VM), in `repeats` rounds over all cases
  // rather than back to back, on `threads` OpenMP threads (0: every core), following the load
  // unless fixed_threads. Wall time: the fastest of the rounds.
  int repeats = 1;
  int threads = 0;
  bool fixed_threads = false;
  int shard_index = 0;  // run cases with id % shard_count == shard_index
  int shard_count = 1;
  bool resume = true;  // keep rows already in the output file and skip their cases
  std::function<void(int done, int total)> progress = nullptr;
  std::function<void(int done, int total)> timing_progress = nullptr;  // the timing rounds
};

// Runs the (remaining) cases of the spec in parallel, appending each finished row to `out_csv`
// as soon as it is done (so an interrupted sweep loses only runs in flight), then rewrites the
// file sorted by case id. Returns the number of cases run now.
[[nodiscard]] std::expected<int, std::string> runSweep(const EngineRegistry& registry,
                                                       const SweepSpec& spec,
                                                       const std::string& out_csv,
                                                       const SweepOptions& options);

// Joins shard tables into one, sorted by case id; duplicate ids must agree on their parameters.
[[nodiscard]] std::expected<int, std::string> mergeSweepTables(
    const std::vector<std::string>& inputs, const std::string& out_csv);

// Reads a results table written by runSweep: header check, rows by id.
[[nodiscard]] std::expected<std::vector<SweepRow>, std::string> readSweepTable(
    const std::string& path);

}  // namespace springcheck
