#pragma once
#include <vector>

#include "mysim/spring.h"

namespace mysim {

// The springs around each particle, in CSR form, so the force on a particle is gathered from its
// own springs (the seed's per-particle spring lists) with no search and no write to another
// particle: particles can be processed in parallel and each sum has a fixed order (the result
// does not depend on the thread count).
//
// A spring (i, j) appears twice, as (i -> j) and (j -> i): twice the arithmetic of a scatter loop,
// none of its write conflicts. Parameters are deduplicated (a cloth has a handful of distinct
// (rest, k, c) triples), so an incidence is 8 bytes.
struct SpringAdjacency {
  struct Parameters {
    double rest_length, stiffness, damping;
  };
  std::vector<int> offsets;    // (N + 1) incidences of particle p: [offsets[p], offsets[p+1])
  std::vector<int> other;      // (2S) the particle at the far end
  std::vector<int> parameter;  // (2S) index into `parameters`
  // (2S) 2 s + 1 if the particle is spring s's second end (its force is minus the spring's
  // force on the first end, spring_forces.h), 2 s if it is the first.
  std::vector<int> spring_end;
  std::vector<Parameters> parameters;

  static SpringAdjacency build(int particle_count, const std::vector<Spring>& springs);
};

}  // namespace mysim
