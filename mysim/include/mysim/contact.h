#pragma once
#include <functional>

#include "mysim/types.h"

namespace mysim {

// Where a particle must go when it touches a static collider: the nearest point of the collider's
// surface grown by its margin, and the outward normal there.
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;  // unit
};

// The frictionless contact every mysim integrator applies after a step (and external engines are
// told to apply): the particle goes to the surface point and loses its inward normal velocity.
// Keeping that velocity (as the seed did) re-enters the collider next step: the seed's jitter.
// Whether a point lies inside another collider: a shape with several ways out (a box's faces)
// takes the nearest one that does not lead into another collider (a box standing on the ground
// must not push a node out through its bottom face, into the ground).
using Blocked = std::function<bool(const Vec3&)>;

inline void applyContact(const SurfacePoint& s, Eigen::Ref<Vec3> x, Eigen::Ref<Vec3> v) {
  x = s.point;
  const double vn = v.dot(s.normal);
  if (vn < 0.0) v -= vn * s.normal;
}

}  // namespace mysim
