#pragma once
// What a collider shape answers about a point near it, and the friction it carries: the types each
// shape's file and the contact (mysim/contact.h) share.
#include <functional>

#include "mysim/types.h"

namespace mysim {

// Where a particle must go when it touches a static collider: the nearest point of the collider's
// surface grown by its margin, and the outward normal there.
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;  // unit
};

// Whether a point lies inside another collider: a shape with several ways out (a box's faces)
// takes the nearest one that does not lead into another collider (a box standing on the ground
// must not push a node out through its bottom face, into the ground).
using Blocked = std::function<bool(const Vec3&)>;

// A collider's Coulomb friction ("friction": {"static": MU_S, "kinetic": MU_K} in a scene; both
// 0, frictionless, when absent): mu_s >= mu_k >= 0.
struct Friction {
  double static_coefficient = 0.0;
  double kinetic = 0.0;
  bool any() const { return static_coefficient > 0.0 || kinetic > 0.0; }
};

}  // namespace mysim
