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

}  // namespace mysim
