#pragma once
// Contacts inside an implicit step. Every integrator ends its step with the contact pass
// (afterStep), which moves a particle found inside a collider back onto its surface. After an
// explicit step that is harmless; after a step with h^2 k / m >> 1 it is not: the solve placed
// the particle's neighbours for where the particle was, and moving it by d afterwards stores
// about k d^2 / 2 in its springs while taking only m (d / h)^2 / 2 of kinetic energy away,
// (h w)^2 times more energy put in than taken out. At h = 1/60 s (h w about 3 on the shipped
// cloths) every implicit family gained energy on landing and blew up within 20 steps.
// So the implicit families solve the step again with such particles held, in rounds, each
// re-solve starting from the last result:
//  1. a particle inside a collider is held on the surface's tangent plane at the point the
//     contact pass would put it on (its normal coordinate fixed, free to slide along it), so its
//     neighbours settle around it and the solve takes the impact's energy out as any other;
//  2. once no new particle is found inside, friction (Coulomb at position level as the contact
//     pass applies it, contact.h: the slide since the step began against the push it was held
//     with) moves the held particles it stops or slows, and they are held there whole;
//  3. then self-collision's pass (self_collision.h) runs on the result, and the particles it
//     moves are held whole where it puts them.
// A round with nothing new ends it; kContactRounds at most, and what is left the closing
// contact pass moves as before (afterStep: it also takes the inward normal velocity away).
#include <vector>

#include "mysim/collider_surface.h"
#include "mysim/particle_system.h"

namespace mysim {

// Rounds a step makes at most: most steps need one or two (docs/performance.md).
inline constexpr int kContactRounds = 6;

struct ContactHold {
  int particle = 0;
  Vec3 point;     // where it is held: on the surface, where the contact pass put it
  Vec3 normal;    // the surface's unit normal there, out of the collider
  bool whole = false;  // held at the point (friction, self-contact), not only on the plane
  Friction friction;
  double pushed = 0.0;  // m: how far inside the collider the solve had it
};

class ContactHolds {
 public:
  // A new step of a system of n particles: nothing held.
  void clear(int n);
  // One round of holds for positions x of the step from x0 by h (the rounds above): moves
  // the particles it holds in x to where they are held; how many it held (0: the step is done).
  int hold(const ParticleSystem& ps, const Vector& x0, double h, Vector& x);
  bool empty() const { return holds_.empty(); }
  const std::vector<ContactHold>& all() const { return holds_; }
  int of(int particle) const { return index_[particle]; }  // its hold, or -1
  // r with each held particle's held part removed (its normal component, or all of it when
  // held whole): the surface's reaction balances it.
  void removeReactions(Vector& r) const;

 private:
  int holdInsideColliders(const ParticleSystem& ps, Vector& x);
  int holdWhereFrictionActs(const Vector& x0, Vector& x);
  int holdSelfContacts(const ParticleSystem& ps, const Vector& x0, double h, Vector& x);
  void holdWhole(int particle, const Vec3& at);

  std::vector<ContactHold> holds_;
  std::vector<int> index_;  // (N) each particle's hold, -1 if none
  Vector trial_x_, trial_v_;  // (3N) self-collision's trial pass
};

// The position on hold's tangent plane nearest x + H^-1 f: the minimiser of the local quadratic
// -f . d + d^T H d / 2 over steps d that keep the particle on the plane (a Lagrange multiplier
// along the normal). VBD's vertex step and backward Euler's test use it.
Vec3 stepOnPlane(const Eigen::LLT<Mat3>& hessian, const Vec3& f, const Vec3& x,
                 const ContactHold& hold);

}  // namespace mysim
