#pragma once
#include <cstdint>
#include <vector>

#include "mysim/types.h"

namespace mysim {

enum class SpringFamily : std::uint8_t { Structural, Shear, Flex, Chain, Custom };
const char* familyName(SpringFamily family);

// A Hooke spring between particles i and j, with damping along the spring.
struct Spring {
  int i = 0;
  int j = 0;
  double rest_length = 1.0;  // m
  double stiffness = 0.0;    // N/m
  double damping = 0.0;      // N s/m, acts on the relative speed along the spring only
  SpringFamily family = SpringFamily::Custom;
};

// Largest |l / rest - 1| over springs, for positions x (3N).
double maxSpringStrain(const std::vector<Spring>& springs, Eigen::Ref<const Vector> x);

// Force on particle i (particle j feels the opposite), d = xj - xi, l = |d|, u = d / l:
//   F_i = [ k (l - rest) + c u.(vj - vi) ] u
Vec3 springForce(const Vec3& xi, const Vec3& xj, const Vec3& vi, const Vec3& vj, double rest,
                 double k, double c);

// dF_i/dxj (and dF_i/dxi = -dF_i/dxj) of the force above, in full:
//   elastic  k [ (1 - rest/l)(I - u u^T) + u u^T ]
//   damping  (c / l) [ (u.w) I + u w^T ] (I - u u^T),   w = vj - vi
// Not symmetric because of the damping part.
Mat3 springPositionJacobian(const Vec3& xi, const Vec3& xj, const Vec3& vi, const Vec3& vj,
                            double rest, double k, double c);

// The elastic part alone with (1 - rest/l) clamped at zero: symmetric positive semi-definite, so
// the backward Euler matrix stays SPD and conjugate gradient applies (Choi and Ko 2002 drop the
// compressive term for the same reason; Baraff and Witkin 1998 drop the damping part).
Mat3 springElasticJacobianDefinite(const Vec3& xi, const Vec3& xj, double rest, double k);

// dF_i/dvj (and dF_i/dvi = -dF_i/dvj) = c u u^T.
Mat3 springVelocityJacobian(const Vec3& xi, const Vec3& xj, double c);

// The backward Euler block of one spring, h C + h^2 J with C and J as above, in the two numbers
// it takes: with a = max(0, 1 - rest / l),
//   h C + h^2 J = alpha I + beta u u^T,  alpha = h^2 k a,  beta = h c + h^2 k (1 - a),
// and J w = k (a w + (1 - a) u (u.w)). Same values as the Mat3 functions (tested), a fraction of
// the arithmetic: this is what the solver's hot loop uses.
struct ImplicitSpringBlock {
  double alpha, beta;  // h C + h^2 J = alpha I + beta u u^T
  double ja, jb;       // J = ja I + jb u u^T
  Vec3 u;
  Mat3 matrix() const { return alpha * Mat3::Identity() + beta * u * u.transpose(); }
  Vec3 timesJ(const Vec3& w) const { return ja * w + jb * u.dot(w) * u; }
};
ImplicitSpringBlock implicitSpringBlock(const Vec3& xi, const Vec3& xj, double rest, double k,
                                        double c, double h);

}  // namespace mysim
