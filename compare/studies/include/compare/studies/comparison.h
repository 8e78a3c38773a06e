#pragma once
#include <expected>
#include <ostream>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "compare/io/run_output.h"
#include "compare/metrics/run_metrics.h"

namespace springcheck {

// A scene run in several engines, with every metric per engine and per pair.
struct Comparison {
  mysim::Model model;
  RunConfig config;  // the scene's run settings the engines ran with
  std::vector<EngineRun> runs;
  // Engines that cannot run the scene, with their message (which names engine and field), and
  // external engines that ran and failed (crashed, timed out, returned a bad result).
  struct Refusal {
    std::string engine, reason;
  };
  std::vector<Refusal> refused;
  std::vector<Refusal> failed;
  std::vector<EngineMetrics> engines;
  std::vector<PairMetrics> pairs;  // every pair of runs that did not blow up
  // The run the others' energy balance is read against in a damped scene, where the balance
  // itself mostly shows the damping: the one stepped by the highest-order fixed-step integrator of
  // the catalogue (RK4 among today's), if the comparison has it.
  std::optional<std::size_t> energy_reference;
  // Scenes compared side by side (suite --jobs) while these runs were timed: above 1, each wall
  // time was measured beside other runs.
  int jobs = 1;
};

// Runs the engines; an engine that refuses the scene is listed in `refused`, one that fails in
// `failed`, not an error. Fails only when an engine name is unknown.
[[nodiscard]] std::expected<Comparison, std::string> compareScene(
    const EngineRegistry& registry, const mysim::Scene& scene,
    const std::vector<std::string>& engines, const Timing& timing = {});

void printComparison(std::ostream& out, const Comparison& c);

// Writes each run into dir/ENGINE/ (the `run` files), and beside them comparison.json (all
// metrics), engine_metrics.csv, pair_metrics.csv, node_distance.csv (each run's final per-node
// distance to the first run's) and series.csv (per frame and engine: time,
// sag of the lowest point and the free edge, deepest penetration, total energy drift). The
// folder is written whole (compare/io/whole_folder.h): this comparison or the previous one.
// Refused: two engines whose names give one folder.
[[nodiscard]] std::expected<void, std::string> writeComparison(const std::string& dir,
                                                               const Comparison& c,
                                                               const RunFileOptions& files = {});
// The same files into `dir` directly (a staging folder).
[[nodiscard]] std::expected<void, std::string> writeComparisonFiles(
    const std::string& dir, const Comparison& c, const RunFileOptions& files = {});

}  // namespace springcheck
