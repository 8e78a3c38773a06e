#pragma once
// Colours for Gauss-Seidel over springs: no two springs of one colour share a particle, so a
// colour's springs can be projected in parallel with the same result as one after another.
#include <vector>

#include "mysim/spring_adjacency.h"
#include "mysim/spring_list.h"

namespace mysim {

// Greedy colouring in spring order (each spring takes the lowest colour free at both its ends):
// deterministic, at most (largest particle degree) * 2 - 1 colours. Returns the springs of each
// colour, each list in spring order.
std::vector<std::vector<int>> colorSprings(int particles, const SpringList& springs);

// Greedy colouring of the particles in index order (each takes the lowest colour none of its
// spring neighbours has): no two particles of a colour share a spring, so vertex block descent
// can relax a colour in parallel. Deterministic; at most (largest degree) + 1 colours. Returns the
// particles of each colour, each list in index order.
std::vector<std::vector<int>> colorParticles(const SpringAdjacency& adjacency);

}  // namespace mysim
