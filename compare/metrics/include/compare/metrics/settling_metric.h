#pragma once
#include <optional>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// Time after which the kinetic energy stays below `relative_threshold` times its peak for the
// rest of the run; none if the last frame is still above it.
std::optional<double> settlingTime(const mysim::RunRecord& run, double relative_threshold = 1e-4);

// Largest |l / rest - 1| of any spring over all frames.
double maxStrainOverRun(const mysim::Model& model, const mysim::RunRecord& run);

}  // namespace springcheck
