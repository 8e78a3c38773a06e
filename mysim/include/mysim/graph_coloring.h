#pragma once
// Colours for Gauss-Seidel over springs: no two springs of one colour share a particle, so a
// colour's springs can be projected in parallel with the same result as one after another.
#include <vector>

#include "mysim/spring_list.h"

namespace mysim {

// Greedy colouring in spring order (each spring takes the lowest colour free at both its ends):
// deterministic, at most (largest particle degree) * 2 - 1 colours. Returns the springs of each
// colour, each list in spring order.
std::vector<std::vector<int>> colorSprings(int particles, const SpringList& springs);

}  // namespace mysim
