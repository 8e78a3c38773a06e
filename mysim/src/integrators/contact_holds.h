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
//     neighbours settle around it and the solve takes the impact's energy out as any other. On
//     a collider with friction it is first held whole (stuck) where it was on that plane when
//     the step began;
//  2. Coulomb's cone on the holds' reactions (the force each hold exerts, the step's residual
//     there): a stuck particle whose tangential reaction exceeds mu_s times its normal one
//     slides instead, held on the plane with kinetic friction mu_k N against that tangential
//     reaction as a force of the step; one pulled off the surface is let go;
//  3. self-collision's pass (self_collision.h) runs on the result, and the particles it moves
//     are held whole where it puts them.
// A round that changes nothing ends the step; kContactRounds at most, and what is left the
// closing contact pass moves as before (afterStep: it also takes the inward normal velocity
// away). Coulomb's law is then the solve's own, on forces, where the contact pass (contact.h)
// applies it to positions after the step.
#include <functional>
#include <vector>

#include "mysim/collider_surface.h"
#include "mysim/particle_system.h"

namespace mysim {

// Re-solves a step makes at most. Measured (local/global at 1/60 s): cloth_on_box re-solves twice
// on 253 of its 300 steps, once on 37; cloth_on_sphere once a step. 8 leaves room for a step
// where contacts, the cone and self-contacts each need their own.
inline constexpr int kContactRounds = 8;

struct ContactHold {
  int particle = 0;
  Vec3 point;     // where it is held: on the surface, where the contact pass put it
  Vec3 normal;    // the surface's unit normal there, out of the collider
  bool whole = false;  // held at the point (stuck, self-contact), not only on the plane
  Friction friction;   // its collider's; none for a self-contact
  Vec3 force = Vec3::Zero();  // kinetic friction on it while it slides: a force of the step
};

// The force each hold exerts on its particle after a solve: the step's residual there, what
// the particle's other forces leave unbalanced (each family's own: implicit_euler_step.h's
// r(x), backward Euler's A dv - b over h).
using HoldReaction = std::function<Vec3(int particle)>;

class ContactHolds {
 public:
  // A new step of a system of n particles: nothing held.
  void clear(int n);
  // One round of holds for positions x of the step from x0 by h (the rounds above): moves
  // the particles it holds in x to where they are held; how many it held (0: the step is done).
  int hold(const ParticleSystem& ps, const Vector& x0, double h, Vector& x,
           const HoldReaction& reaction);
  bool empty() const { return holds_.empty(); }
  const std::vector<ContactHold>& all() const { return holds_; }
  int of(int particle) const { return index_[particle]; }  // its hold, or -1
  // r with each held particle's held part removed (its normal component, or all of it when
  // held whole): the surface's reaction balances it. Friction's forces are in r already.
  void removeReactions(Vector& r) const;

 private:
  int holdInsideColliders(const ParticleSystem& ps, const Vector& x0, Vector& x);
  int applyCoulombCone(const HoldReaction& reaction);
  int holdSelfContacts(const ParticleSystem& ps, const Vector& x0, double h, Vector& x);
  void holdWhole(int particle, const Vec3& at);

  std::vector<ContactHold> holds_;
  std::vector<int> index_;  // (N) each particle's hold, -1 if none
  Vector trial_x_, trial_v_;  // (3N) self-collision's trial pass
};

// The position on hold's tangent plane nearest x + H^-1 f: the minimiser of the local quadratic
// -f . d + d^T H d / 2 over steps d that keep the particle on the plane (a Lagrange multiplier
// along the normal). VBD's vertex step uses it.
Vec3 stepOnPlane(const Eigen::LLT<Mat3>& hessian, const Vec3& f, const Vec3& x,
                 const ContactHold& hold);

}  // namespace mysim
