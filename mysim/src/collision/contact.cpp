#include "mysim/contact.h"

#include <algorithm>

namespace mysim {
namespace {

// The part of u across the unit normal n.
Vec3 tangential(const Vec3& u, const Vec3& n) { return u - u.dot(n) * n; }

// Coulomb's law on what the normal projection removed: `pushed` (m, the normal displacement put
// back) and `stopped` (m/s, the inward normal velocity taken away).
void applyFriction(const Friction& friction, const Vec3& n, double pushed, double stopped,
                   const Vec3& start, Eigen::Ref<Vec3> x, Eigen::Ref<Vec3> v) {
  const Vec3 slid = tangential(x - start, n);
  const double slid_length = slid.norm();
  const Vec3 vt = tangential(v, n);
  // Sticks (the step's slide undone) when static friction can stop both the slide and the
  // velocity: a particle placed on the surface moving, with nothing pressed yet, slides on.
  if (slid_length <= friction.static_coefficient * pushed &&
      vt.norm() <= friction.static_coefficient * stopped) {
    x -= slid;
    v -= vt;
    return;
  }
  x -= slid * std::min(1.0, friction.kinetic * pushed / slid_length);
  const double speed = vt.norm();
  if (speed > 0.0) v -= vt * std::min(1.0, friction.kinetic * stopped / speed);
}

}  // namespace

void applyContact(const SurfacePoint& s, const Friction& friction, const Vec3& start,
                  Eigen::Ref<Vec3> x, Eigen::Ref<Vec3> v) {
  const double pushed = std::max(0.0, (s.point - x).dot(s.normal));
  x = s.point;
  const double vn = v.dot(s.normal);
  if (vn < 0.0) v -= vn * s.normal;
  if (friction.any()) applyFriction(friction, s.normal, pushed, std::max(0.0, -vn), start, x, v);
}

std::vector<Blocked> insideAnotherCollider(const std::vector<Collider>& colliders) {
  std::vector<Blocked> inside_another;
  for (std::size_t k = 0; k < colliders.size(); ++k) {
    inside_another.push_back([&colliders, k](const Vec3& point) {
      for (std::size_t o = 0; o < colliders.size(); ++o) {
        if (o != k && signedDistance(colliders[o], point) < 0.0) return true;
      }
      return false;
    });
  }
  return inside_another;
}

std::optional<FirstContact> firstContact(const std::vector<Collider>& colliders,
                                         const std::vector<Blocked>& inside_another, const Vec3& x,
                                         const Vec3& from) {
  for (std::size_t k = 0; k < colliders.size(); ++k) {
    if (const auto s = contactPoint(colliders[k], x, inside_another[k], from)) {
      return FirstContact{*s, k};
    }
  }
  return std::nullopt;
}

int resolveContacts(const std::vector<Collider>& colliders, const std::vector<char>& pinned,
                    Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x, Eigen::Ref<Vector> v) {
  const std::vector<Blocked> inside_another = insideAnotherCollider(colliders);
  int contacts = 0;
  for (int p = 0; p < static_cast<int>(pinned.size()); ++p) {
    if (pinned[p]) continue;
    const Vec3 from = start.segment<3>(3 * p);  // where it was as the step began
    for (std::size_t k = 0; k < colliders.size(); ++k) {
      if (const auto s = contactPoint(colliders[k], x.segment<3>(3 * p), inside_another[k], from)) {
        applyContact(*s, colliderFriction(colliders[k]), from, x.segment<3>(3 * p),
                     v.segment<3>(3 * p));
        ++contacts;
      }
    }
  }
  return contacts;
}

}  // namespace mysim
