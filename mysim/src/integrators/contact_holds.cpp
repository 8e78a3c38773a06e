#include "integrators/contact_holds.h"

#include <algorithm>

#include "mysim/contact.h"

namespace mysim {

void ContactHolds::clear(int n) {
  holds_.clear();
  index_.assign(n, -1);
}

int ContactHolds::hold(const ParticleSystem& ps, const Vector& x0, double h, Vector& x,
                       const HoldReaction& reaction) {
  if (const int held = holdInsideColliders(ps, x0, x)) return held;
  if (const int changed = applyCoulombCone(reaction)) return changed;
  return holdSelfContacts(ps, x0, h, x);
}

int ContactHolds::holdInsideColliders(const ParticleSystem& ps, const Vector& x0, Vector& x) {
  const Model& model = ps.model();
  if (model.colliders.empty()) return 0;
  const std::vector<Blocked> inside_another = insideAnotherCollider(model.colliders);
  int held = 0;
  for (int p = 0; p < ps.particleCount(); ++p) {
    if (model.pinned[p] || index_[p] >= 0) continue;
    const Vec3 at = x.segment<3>(3 * p);
    const Vec3 start = x0.segment<3>(3 * p);
    const auto contact = firstContact(model.colliders, inside_another, at, start);
    if (!contact) continue;
    const SurfacePoint& s = contact->surface;
    const Friction& friction = colliderFriction(model.colliders[contact->collider]);
    // With friction it is tried stuck: on the plane where it was when the step began.
    const Vec3 point = friction.any() ? Vec3(start - (start - s.point).dot(s.normal) * s.normal) : s.point;
    index_[p] = static_cast<int>(holds_.size());
    holds_.push_back({p, point, s.normal, friction.any(), friction});
    x.segment<3>(3 * p) = point;
    ++held;
  }
  return held;
}

int ContactHolds::applyCoulombCone(const HoldReaction& reaction) {
  int changed = 0;
  for (ContactHold& hold : holds_) {
    if (!hold.whole || !hold.friction.any()) continue;
    const Vec3 r = reaction(hold.particle);
    const double normal = r.dot(hold.normal);
    const Vec3 tangential = r - normal * hold.normal;
    const double needed = tangential.norm();
    if (normal >= 0.0 && needed <= hold.friction.static_coefficient * normal) continue;
    ++changed;
    if (normal <= 0.0) {  // pulled off the surface: let go
      hold.particle = -1;
      continue;
    }
    // It slides: on its plane, with kinetic friction along the tangential force the hold had
    // to supply (against the slide that force was holding back).
    hold.whole = false;
    hold.force = tangential * (hold.friction.kinetic * normal / needed);
  }
  if (changed) {  // the let-go ones out, the index rebuilt
    std::erase_if(holds_, [](const ContactHold& h) { return h.particle < 0; });
    std::fill(index_.begin(), index_.end(), -1);
    for (std::size_t k = 0; k < holds_.size(); ++k) index_[holds_[k].particle] = static_cast<int>(k);
  }
  return changed;
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
    holds_.push_back({particle, at, Vec3::UnitY(), true, {}});
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
