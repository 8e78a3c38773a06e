#pragma once
// The settled shape's quantities of one run: every catalogue metric marked `refined` (tip drop,
// chord angle, bending length, sag, drape coefficient, folds) that the run has, read at its last
// frame and at the frame a tenth of the run earlier. A quantity that still moves between the two
// has not settled, and its value is not the equilibrium the physical reference describes
// (springcheck trade never recommends such a run; docs/trade.md).
#include <map>
#include <string>

#include "compare/metrics/run_metrics.h"

namespace springcheck {

struct SettledQuantity {
  double end = 0.0;      // at the last frame
  double earlier = 0.0;  // at the last frame at or before 0.9 of the run's end time
  double drift() const { return end - earlier; }
};
using SettledQuantities = std::map<std::string, SettledQuantity>;

// `end`: the run's own metrics (engineMetrics of the whole run). Empty for a run that blew up or
// sampled fewer than two frames.
SettledQuantities settledQuantities(const mysim::Model& model, const EngineRun& run,
                                    const EngineMetrics& end);

}  // namespace springcheck
