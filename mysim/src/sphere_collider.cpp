#include "mysim/sphere_collider.h"

#include <algorithm>
#include <cmath>

namespace mysim {

int resolveSphereContacts(const Sphere& sphere, const std::vector<char>& pinned,
                          Eigen::Ref<Vector> x, Eigen::Ref<Vector> v) {
  const double surface = sphere.radius + sphere.margin;
  int moved = 0;
  for (int p = 0; p < static_cast<int>(pinned.size()); ++p) {
    if (pinned[p]) continue;
    const Vec3 d = x.segment<3>(3 * p) - sphere.center;
    const double r2 = d.squaredNorm();
    if (r2 >= surface * surface) continue;
    const double r = std::sqrt(r2);
    // A particle exactly at the centre has no outward direction: push it up (+y).
    const Vec3 n = r > 0.0 ? Vec3(d / r) : Vec3::UnitY();
    x.segment<3>(3 * p) = sphere.center + surface * n;
    const double vn = v.segment<3>(3 * p).dot(n);
    if (vn < 0.0) v.segment<3>(3 * p) -= vn * n;
    ++moved;
  }
  return moved;
}

double deepestPenetration(const Sphere& sphere, const Vector& x) {
  double deepest = 0.0;
  for (int p = 0; p < static_cast<int>(x.size() / 3); ++p) {
    deepest = std::max(deepest, sphere.radius - (at3(x, p) - sphere.center).norm());
  }
  return deepest;
}

}  // namespace mysim
