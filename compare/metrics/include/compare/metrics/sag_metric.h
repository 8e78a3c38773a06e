#pragma once
#include <optional>
#include <vector>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// How far below the pins the cloth or chain hangs, per frame, in m along gravity (-y without
// gravity). The pin level is the mean height of the pinned particles in that frame (so driven
// pins are followed); without pins, the highest particle at the start.
struct SagSeries {
  std::vector<double> lowest;       // the lowest particle
  std::vector<double> free_middle;  // the middle of the free edge: a cloth's bottom row (mean of
                                    // the two middle nodes for an even count), a chain's end;
                                    // empty for other systems
};
SagSeries sagOverTime(const mysim::Model& model, const mysim::RunRecord& run);

}  // namespace springcheck
