#pragma once
// "pins" of a chain or a cloth, read (scene_kind.cpp): internal to mysim's scene kinds.
#include <vector>

#include "mysim/json_input.h"

namespace mysim {

// system.pins: a list of particle indices in [0, count), each once, or a preset ("none"; for a
// grid of rows x cols also "top_corners" and "corners"); `fallback` when the scene is silent.
// rows = 0: not a grid.
std::vector<int> readPins(FieldReader& system, int count, const std::vector<int>& fallback,
                          int rows, int cols);

}  // namespace mysim
