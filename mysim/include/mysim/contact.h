#pragma once
#include <optional>
#include <vector>

#include "mysim/collider.h"
#include "mysim/collider_surface.h"
#include "mysim/types.h"

namespace mysim {

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

// Whether a point is inside any collider but the k-th, for each k: the exits a collider's
// contact must avoid (Blocked), built once for a pass over the particles.
std::vector<Blocked> insideAnotherCollider(const std::vector<Collider>& colliders);

// Where a particle at x first touches a collider (the model's order, as resolveContacts takes
// them): the surface point the contact pass puts it on and the collider's index; none if it
// touches none. `inside_another` from insideAnotherCollider.
struct FirstContact {
  SurfacePoint surface;
  std::size_t collider = 0;
};
std::optional<FirstContact> firstContact(const std::vector<Collider>& colliders,
                                         const std::vector<Blocked>& inside_another, const Vec3& x,
                                         const Vec3& from);

// After a step: every free particle touching a collider goes onto its surface (applyContact),
// colliders in the model's order, each avoiding exits into the others (a box's bottom face on
// the ground), with the collider's friction against the particle's position when the step
// began (`start`, 3N). Returns how many contacts were applied.
int resolveContacts(const std::vector<Collider>& colliders, const std::vector<char>& pinned,
                    Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x, Eigen::Ref<Vector> v);

}  // namespace mysim
