#include "mysim/spring.h"

#include <algorithm>
#include <cmath>

namespace mysim {

const char* familyName(SpringFamily family) {
  switch (family) {
    case SpringFamily::Structural:
      return "structural";
    case SpringFamily::Shear:
      return "shear";
    case SpringFamily::Flex:
      return "flex";
    case SpringFamily::Chain:
      return "chain";
    case SpringFamily::Custom:
      return "custom";
  }
  return "custom";
}

double maxSpringStrain(const std::vector<Spring>& springs, Eigen::Ref<const Vector> x) {
  double worst = 0.0;
  for (const Spring& s : springs) {
    const double l = (x.segment<3>(3 * s.j) - x.segment<3>(3 * s.i)).norm();
    worst = std::max(worst, std::abs(l / s.rest_length - 1.0));
  }
  return worst;
}

Vec3 springForce(const Vec3& xi, const Vec3& xj, const Vec3& vi, const Vec3& vj, double rest,
                 double k, double c) {
  const Vec3 d = xj - xi;
  const double l = d.norm();
  const Vec3 u = d / l;
  return (k * (l - rest) + c * u.dot(vj - vi)) * u;
}

Mat3 springPositionJacobian(const Vec3& xi, const Vec3& xj, const Vec3& vi, const Vec3& vj,
                            double rest, double k, double c) {
  const Vec3 d = xj - xi;
  const double l = d.norm();
  const Vec3 u = d / l;
  const Mat3 uu = u * u.transpose();
  const Mat3 tangent = Mat3::Identity() - uu;  // du/dd = tangent / l
  const Vec3 w = vj - vi;
  const Mat3 elastic = k * ((1.0 - rest / l) * tangent + uu);
  const Mat3 damping = (c / l) * (u.dot(w) * Mat3::Identity() + u * w.transpose()) * tangent;
  return elastic + damping;
}

Mat3 springElasticJacobianDefinite(const Vec3& xi, const Vec3& xj, double rest, double k) {
  const Vec3 d = xj - xi;
  const double l = d.norm();
  const Vec3 u = d / l;
  const Mat3 uu = u * u.transpose();
  return k * (std::max(0.0, 1.0 - rest / l) * (Mat3::Identity() - uu) + uu);
}

Mat3 springVelocityJacobian(const Vec3& xi, const Vec3& xj, double c) {
  const Vec3 u = (xj - xi).normalized();
  return c * u * u.transpose();
}

ImplicitSpringBlock implicitSpringBlock(const Vec3& xi, const Vec3& xj, double rest, double k,
                                        double c, double h) {
  const Vec3 d = xj - xi;
  const double l = d.norm();
  const double a = std::max(0.0, 1.0 - rest / l);
  return {h * h * k * a, h * c + h * h * k * (1.0 - a), k * a, k * (1.0 - a), d / l};
}

}  // namespace mysim
