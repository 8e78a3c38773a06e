#pragma once
#include <vector>

#include "mysim/collider.h"
#include "mysim/simulation.h"

namespace springcheck {

// Nodes inside any of the model's colliders in one frame; a node's depth is how far it is inside
// its deepest collider (minus its signed distance), in m. The one penetration measure: runs,
// comparisons and the viewer all use it.
struct Penetration {
  double deepest = 0.0;
  double mean_depth = 0.0;  // over penetrating nodes only (0 if none)
  int count = 0;
};
Penetration penetration(const std::vector<mysim::Collider>& colliders,
                        Eigen::Ref<const mysim::ParticleRows> positions);
std::vector<Penetration> penetrationOverTime(const std::vector<mysim::Collider>& colliders,
                                             const mysim::RunRecord& run);

}  // namespace springcheck
