#pragma once
// The refinement study behind `springcheck refine`: each material scene at several resolutions in
// each engine, the shape quantities each run settles to (the metric catalogue's `refined` ones),
// and per scene, engine and quantity the observed order and the Richardson limit
// (refinement.h), beside the closed form where the scene has one.
#include <cmath>
#include <expected>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "compare/studies/refinement.h"

namespace springcheck {

struct RefineRow {
  std::string scene, bending, engine;
  std::string status;  // RunRecord::status(), or "refused"
  int resolution = 0;
  int particles = 0;
  double wall_seconds = 0.0;
  int jobs = 1;  // runs side by side while this one was timed
  std::map<std::string, double> values;  // each refined metric the run has
  double reference = NAN;  // the closed form's value of reference_quantity, where there is one
  std::string reference_quantity;
  // Why the run has no values (refused, blew up), or why it has no closed form to be held to.
  std::string note;
  // The order at which the discretisation's smooth quantities converge, where theory and
  // measurement give one (refine_study.cpp: expectedOrder).
  std::optional<double> expected_order;
};

struct RefineSettings {
  std::vector<std::string> scenes;  // material scene files (system.material)
  std::vector<int> resolutions;     // increasing, distinct
  std::vector<std::string> engines;
  Timing timing;
  // Runs side by side (jobCount's rule; 0: every free core). None of the study's answers is a
  // time: wall_seconds is kept with the jobs it was measured beside.
  int jobs = 0;
  std::function<void(int done, int total)> progress = nullptr;  // from any thread, one at a time
};

// Every run, in the order scene, resolution, engine; the error names a scene file that cannot be
// read at a resolution.
[[nodiscard]] std::expected<std::vector<RefineRow>, std::string> runRefinement(
    const EngineRegistry& registry, const RefineSettings& settings);

struct RefineEstimateRow {
  std::string scene, bending, engine, quantity, unit;
  std::vector<int> resolutions;  // the completed runs that have the quantity
  std::vector<double> values;
  RefinementEstimate estimate;
  std::optional<double> expected_order;  // none for a count or a model with no consistent order
  // Whether the estimate may be quoted (refinementVerdict): without it the tables leave the
  // order and the limit empty and the report draws neither.
  RefinementVerdict verdict;
  double reference = NAN;  // the closed form at the finest resolution, where there is one
  double finestVsLimit() const;      // relative; NaN without a limit
  double finestVsReference() const;  // relative; NaN without a closed form
};
// Per scene, engine and quantity, from the runs that completed.
std::vector<RefineEstimateRow> refinementEstimates(const std::vector<RefineRow>& rows);

// refine.csv and refine_estimates.csv (docs/materials.md).
std::string refineTableCsv(const std::vector<RefineRow>& rows);
std::string refineEstimatesCsv(const std::vector<RefineEstimateRow>& estimates);

}  // namespace springcheck
