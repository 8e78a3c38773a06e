#pragma once
#include <vector>

#include "mysim/spring.h"

namespace mysim {

// The springs around each particle, in CSR form, so the force on a particle is gathered from its
// own springs (the seed's per-particle spring lists) with no search and no write to another
// particle: particles can be processed in parallel and each sum has a fixed order (the result
// does not depend on the thread count). A spring (i, j) appears twice, as (i -> j) and (j -> i);
// an incidence is 8 bytes, the spring's parameters stay in the model's spring list.
struct SpringAdjacency {
  std::vector<int> offsets;  // (N + 1) incidences of particle p: [offsets[p], offsets[p+1])
  std::vector<int> other;    // (2S) the particle at the far end
  std::vector<int> spring;   // (2S) the spring, an index into the model's springs

  static SpringAdjacency build(int particle_count, const std::vector<Spring>& springs);
};

}  // namespace mysim
