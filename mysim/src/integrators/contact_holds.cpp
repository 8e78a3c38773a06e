#include "mysim/contact_holds.h"

#include "mysim/contact.h"

namespace mysim {

void ContactHolds::clear(int n) {
  holds_.clear();
  index_.assign(n, -1);
}

int ContactHolds::hold(const ParticleSystem& ps, const Vector& x0, double h, Vector& x) {
  if (const int held = holdInsideColliders(ps, x)) return held;
  if (const int held = holdWhereFrictionActs(x0, x)) return held;
  return holdSelfContacts(ps, x0, h, x);
}

int ContactHolds::holdInsideColliders(const ParticleSystem& ps, Vector& x) {
  const Model& model = ps.model();
  if (model.colliders.empty()) return 0;
  const std::vector<Blocked> inside_another = insideAnotherCollider(model.colliders);
  int held = 0;
  for (int p = 0; p < ps.particleCount(); ++p) {
    if (model.pinned[p] || index_[p] >= 0) continue;
    const Vec3 at = x.segment<3>(3 * p);
    const auto contact = firstContact(model.colliders, inside_another, at);
    if (!contact) continue;
    const SurfacePoint& s = contact->surface;
    index_[p] = static_cast<int>(holds_.size());
    holds_.push_back({p, s.point, s.normal, false,
                      colliderFriction(model.colliders[contact->collider]),
                      std::max(0.0, (s.point - at).dot(s.normal))});
    x.segment<3>(3 * p) = s.point;
    ++held;
  }
  return held;
}

int ContactHolds::holdWhereFrictionActs(const Vector& x0, Vector& x) {
  int held = 0;
  for (ContactHold& hold : holds_) {
    if (hold.whole || !hold.friction.any()) continue;
    auto xp = x.segment<3>(3 * hold.particle);
    Vec3 slowed = xp;
    Vec3 no_velocity = Vec3::Zero();  // velocities follow from positions, (x - x0) / h
    applyFriction(hold.friction, hold.normal, hold.pushed, 0.0, x0.segment<3>(3 * hold.particle),
                  slowed, no_velocity);
    if (slowed == Vec3(xp)) continue;
    hold.whole = true;
    hold.point = slowed;
    xp = slowed;
    ++held;
  }
  return held;
}

int ContactHolds::holdSelfContacts(const ParticleSystem& ps, const Vector& x0, double h, Vector& x) {
  if (!ps.hasSelfCollision()) return 0;
  trial_x_ = x;
  trial_v_ = (x - x0) / h;
  ps.selfContactPass(x0, trial_x_, trial_v_);
  int held = 0;
  for (int p = 0; p < ps.particleCount(); ++p) {
    if (ps.model().pinned[p] || trial_x_.segment<3>(3 * p) == x.segment<3>(3 * p)) continue;
    const int existing = index_[p];
    if (existing >= 0 && holds_[existing].whole) continue;  // held whole already: stays
    holdWhole(p, trial_x_.segment<3>(3 * p));
    x.segment<3>(3 * p) = trial_x_.segment<3>(3 * p);
    ++held;
  }
  return held;
}

void ContactHolds::holdWhole(int particle, const Vec3& at) {
  if (index_[particle] < 0) {
    index_[particle] = static_cast<int>(holds_.size());
    holds_.push_back({particle, at, Vec3::UnitY(), true, {}, 0.0});
    return;
  }
  ContactHold& hold = holds_[index_[particle]];
  hold.whole = true;
  hold.point = at;
}

void ContactHolds::removeReactions(Vector& r) const {
  for (const ContactHold& h : holds_) {
    auto rp = r.segment<3>(3 * h.particle);
    if (h.whole) {
      rp.setZero();
    } else {
      rp -= rp.dot(h.normal) * h.normal;
    }
  }
}

Vec3 stepOnPlane(const Eigen::LLT<Mat3>& hessian, const Vec3& f, const Vec3& x,
                 const ContactHold& hold) {
  // d = H^-1 (f + lambda n) with n . (x + d) = n . point.
  const Vec3 free_step = hessian.solve(f);
  const Vec3 along_normal = hessian.solve(hold.normal);
  const double lambda =
      (hold.normal.dot(hold.point - x) - hold.normal.dot(free_step)) / hold.normal.dot(along_normal);
  return x + free_step + lambda * along_normal;
}

}  // namespace mysim
