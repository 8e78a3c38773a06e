// Spring force terms alone: the analytic Jacobians against central finite differences.
// ctest-label: unit
#include "mysim/spring.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "mysim/model.h"

namespace mysim {
namespace {

const Vec3 xi(0.1, -0.2, 0.3), xj(0.9, 0.4, -0.1), vi(0.5, -1.0, 0.2), vj(-0.3, 0.7, 1.1);
const double k = 150.0, c = 2.5;

// d F_i / d (something of particle j) by central differences, column by column.
template <typename Force>
Mat3 finiteDifference(Force force, const Vec3& at) {
  const double eps = 1e-6;
  Mat3 J;
  for (int col = 0; col < 3; ++col) {
    Vec3 plus = at, minus = at;
    plus[col] += eps;
    minus[col] -= eps;
    J.col(col) = (force(plus) - force(minus)) / (2 * eps);
  }
  return J;
}

// Central differences err by O(eps^2 |F'''|) + round-off O(|F| 1e-16 / eps): ~1e-8 here.
constexpr double kFdTolerance = 1e-6;

TEST(SpringJacobian, PositionJacobianMatchesFiniteDifferencesStretchedAndCompressed) {
  for (double rest : {0.5, 1.0, 2.0}) {  // |xj - xi| = 1.08: stretched, near rest, compressed
    const Mat3 analytic = springPositionJacobian(xi, xj, vi, vj, rest, k, c);
    const Mat3 numeric =
        finiteDifference([&](const Vec3& x) { return springForce(xi, x, vi, vj, rest, k, c); }, xj);
    EXPECT_LT((analytic - numeric).norm(), kFdTolerance * analytic.norm()) << rest;
    // dF_i/dxi is the negative: the force depends on xj - xi only.
    const Mat3 numeric_i =
        finiteDifference([&](const Vec3& x) { return springForce(x, xj, vi, vj, rest, k, c); }, xi);
    EXPECT_LT((analytic + numeric_i).norm(), kFdTolerance * analytic.norm()) << rest;
  }
}

TEST(SpringJacobian, VelocityJacobianMatchesFiniteDifferences) {
  const Mat3 analytic = springVelocityJacobian(xi, xj, c);
  const Mat3 numeric =
      finiteDifference([&](const Vec3& v) { return springForce(xi, xj, vi, v, 1.0, k, c); }, vj);
  EXPECT_LT((analytic - numeric).norm(), kFdTolerance * analytic.norm());
}

TEST(SpringJacobian, DefiniteElasticJacobianIsTheExactOneWhenStretchedAndPsdWhenCompressed) {
  const Mat3 stretched = springElasticJacobianDefinite(xi, xj, 0.5, k);
  EXPECT_LT((stretched - springPositionJacobian(xi, xj, vi, vj, 0.5, k, 0.0)).norm(), 1e-12 * k);
  const Mat3 compressed = springElasticJacobianDefinite(xi, xj, 2.0, k);
  Eigen::SelfAdjointEigenSolver<Mat3> eig(compressed);
  EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * k);
  // The exact compressed Jacobian is indefinite: the clamp is what makes CG applicable.
  Eigen::SelfAdjointEigenSolver<Mat3> exact(springPositionJacobian(xi, xj, vi, vj, 2.0, k, 0.0));
  EXPECT_LT(exact.eigenvalues().minCoeff(), 0.0);
}

TEST(SpringForce, HookeMagnitudeAndDampingAlongTheSpring) {
  // Particles 2 m apart on x, rest 1.5 m: tension k * 0.5 pulls i towards j (+x).
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  EXPECT_TRUE(springForce(a, b, Vec3::Zero(), Vec3::Zero(), 1.5, k, 0).isApprox(Vec3(75, 0, 0)));
  // Relative velocity across the spring does not damp; along it does.
  EXPECT_TRUE(springForce(a, b, Vec3::Zero(), Vec3(0, 3, 0), 2.0, k, c).isZero(1e-15));
  EXPECT_TRUE(springForce(a, b, Vec3::Zero(), Vec3(3, 0, 0), 2.0, k, c).isApprox(Vec3(7.5, 0, 0)));
}

}  // namespace
}  // namespace mysim

namespace mysim {
namespace {

TEST(SpringJacobian, ImplicitBlockEqualsHTimesDampingPlusHSquaredTimesDefiniteJacobian) {
  const double h = 0.01;
  for (double rest : {0.5, 2.0}) {  // stretched and compressed
    const ImplicitSpringBlock b = implicitSpringBlock(xi, xj, rest, k, c, h);
    const Mat3 J = springElasticJacobianDefinite(xi, xj, rest, k);
    const Mat3 expected = h * springVelocityJacobian(xi, xj, c) + h * h * J;
    EXPECT_LT((b.matrix() - expected).norm(), 1e-12 * expected.norm()) << rest;
    const Vec3 w(0.3, -0.2, 0.9);
    EXPECT_LT((b.timesJ(w) - J * w).norm(), 1e-12 * (J * w).norm()) << rest;
  }
}

}  // namespace
}  // namespace mysim

namespace mysim {
namespace {

TEST(SpringList, CopiesShareOneListUntilOneOfThemChanges) {
  Model a;
  a.springs = {{0, 1, 1.0, 10.0, 0.0, SpringFamily::Custom},
               {1, 2, 1.0, 10.0, 0.0, SpringFamily::Custom}};
  const Model b = a;
  EXPECT_TRUE(b.springs.sharesWith(a.springs));
  scaleStiffness(a, 2.0);
  EXPECT_FALSE(b.springs.sharesWith(a.springs));
  EXPECT_EQ(a.springs[1].stiffness, 20.0);
  EXPECT_EQ(b.springs[1].stiffness, 10.0);  // the copy kept its own values
  Model c = b;
  c.springs.push_back({2, 3, 1.0, 5.0, 0.0, SpringFamily::Custom});
  EXPECT_EQ(b.springs.size(), 2u);
  EXPECT_EQ(c.springs.size(), 3u);
}

}  // namespace
}  // namespace mysim
