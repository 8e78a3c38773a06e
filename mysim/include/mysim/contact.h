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

// The contact every mysim integrator applies after a step (and external engines are told to
// apply): the particle goes to the surface point and loses its inward normal velocity. Keeping
// that velocity (as the seed did) re-enters the collider next step: the seed's jitter.
// With friction, Coulomb's law on the same projection (projected, not regularised: a
// regularised law creeps at every slope, so nothing would ever stick), at position and velocity
// level as position-based dynamics does (Macklin et al. 2014, "Unified particle physics", 6.1):
// the normal push-out over the step, dn, bounds the tangential correction as the normal
// impulse bounds friction's. The tangential displacement since the step began (`start`, the
// position after the previous step) is undone whole when it is within mu_s dn (sticking), else
// shortened by mu_k dn; the tangential velocity likewise loses all of itself or mu_k times the
// normal velocity removed. On an incline this sticks exactly when tan(theta) <= mu_s, and slides
// with g (sin(theta) - mu_k cos(theta)) whatever the integrator (docs/contact.md derives both).
void applyContact(const SurfacePoint& s, const Friction& friction, const Vec3& start,
                  Eigen::Ref<Vec3> x, Eigen::Ref<Vec3> v);

}  // namespace mysim
