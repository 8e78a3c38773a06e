#pragma once
#include <vector>

#include "mysim/types.h"

namespace mysim {

// A static frictionless sphere. Particles found inside after a step are moved to radius + margin
// and lose their inward normal velocity: keeping that velocity (as the seed did) re-enters the
// sphere next step, which is the jitter the seed left open.
struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;  // m
  double margin = 0.0;  // m, the surface particles are put back on is radius + margin
};

// Returns how many particles were moved.
int resolveSphereContacts(const Sphere& sphere, const std::vector<char>& pinned,
                          Eigen::Ref<Vector> x, Eigen::Ref<Vector> v);

// Deepest penetration below radius (0 if none), in m.
double deepestPenetration(const Sphere& sphere, const Vector& x);

}  // namespace mysim
