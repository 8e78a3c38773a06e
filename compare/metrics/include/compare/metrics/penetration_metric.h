#pragma once
#include <vector>

#include "mysim/simulation.h"
#include "mysim/sphere_collider.h"

namespace springcheck {

// Nodes inside a sphere in one frame; depths in m below the radius.
struct Penetration {
  double deepest = 0.0;
  double mean_depth = 0.0;  // over penetrating nodes only (0 if none)
  int count = 0;
};
Penetration penetration(const mysim::Sphere& sphere, const mysim::ParticleRows& frame);
std::vector<Penetration> penetrationOverTime(const mysim::Sphere& sphere,
                                             const mysim::RunRecord& run);

}  // namespace springcheck
