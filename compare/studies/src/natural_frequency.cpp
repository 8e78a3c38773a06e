#include "compare/studies/natural_frequency.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mysim/spring.h"

namespace springcheck {

namespace {

// M^-1/2 K M^-1/2 on the free coordinates of a model at its start state (pinned ones held at
// zero), applied spring by spring: K x sums each spring's 3x3 block (K_ii = sum J, K_ij = -J).
class MassNormalisedStiffness {
 public:
  explicit MassNormalisedStiffness(const mysim::Model& model) : model_(model) {
    const int particles = model.particleCount();
    std::vector<int> free;  // particle of each free slot
    for (int p = 0; p < particles; ++p) {
      if (!model.pinned[p]) free.push_back(p);
    }
    n_ = 3 * static_cast<int>(free.size());
    slot_.assign(particles, -1);
    for (std::size_t s = 0; s < free.size(); ++s) slot_[free[s]] = static_cast<int>(s);
    blocks_.reserve(model.springs.size());
    const auto& x0 = model.start_position;
    for (const mysim::Spring& s : model.springs) {
      blocks_.push_back(mysim::springElasticJacobianDefinite(
          x0.segment<3>(3 * s.i), x0.segment<3>(3 * s.j), s.rest_length, s.stiffness));
    }
    inv_sqrt_mass_.resize(n_);
    for (std::size_t s = 0; s < free.size(); ++s) {
      inv_sqrt_mass_.segment<3>(3 * s).setConstant(1.0 / std::sqrt(model.mass[free[s]]));
    }
  }
  int size() const { return n_; }

  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
    const Eigen::VectorXd u = inv_sqrt_mass_.cwiseProduct(v);
    y.setZero(n_);
    for (std::size_t k = 0; k < model_.springs.size(); ++k) {
      const int a = slot_[model_.springs[k].i], b = slot_[model_.springs[k].j];
      const mysim::Vec3 ua = a >= 0 ? mysim::Vec3(u.segment<3>(3 * a)) : mysim::Vec3::Zero();
      const mysim::Vec3 ub = b >= 0 ? mysim::Vec3(u.segment<3>(3 * b)) : mysim::Vec3::Zero();
      const mysim::Vec3 f = blocks_[k] * (ua - ub);
      if (a >= 0) y.segment<3>(3 * a) += f;
      if (b >= 0) y.segment<3>(3 * b) -= f;
    }
    y = inv_sqrt_mass_.cwiseProduct(y);
  }

 private:
  const mysim::Model& model_;
  int n_ = 0;
  std::vector<int> slot_;  // free slot of each particle, -1 if pinned
  std::vector<mysim::Mat3> blocks_;
  Eigen::VectorXd inv_sqrt_mass_;
};

// The largest eigenvalue of a symmetric operator by Lanczos with full reorthogonalisation: the
// extreme Ritz value converges first, even when the top of the spectrum is crowded (a cloth's
// is). The basis is capped at ~32 MB. Seeded: the same answer every run.
double largestEigenvalue(const MassNormalisedStiffness& op) {
  const int n = op.size();
  const int steps = std::min({n, 100, std::max(30, 4'000'000 / n)});
  Eigen::MatrixXd basis(n, steps);
  std::vector<double> alpha, beta;
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd q(n), w(n);
  for (int i = 0; i < n; ++i) q[i] = uniform(random);
  q.normalize();
  for (int k = 0; k < steps; ++k) {
    basis.col(k) = q;
    op.apply(q, w);
    alpha.push_back(q.dot(w));
    // Against every earlier vector, twice ("twice is enough", Kahan-Parlett).
    for (int pass = 0; pass < 2; ++pass) {
      w -= basis.leftCols(k + 1) * (basis.leftCols(k + 1).transpose() * w);
    }
    const double b = w.norm();
    if (k + 1 == steps || b <= 1e-12 * std::abs(alpha.front()) + 1e-300) break;
    beta.push_back(b);
    q = w / b;
  }
  const int m = static_cast<int>(alpha.size());
  Eigen::VectorXd diagonal = Eigen::Map<Eigen::VectorXd>(alpha.data(), m);
  Eigen::VectorXd off = Eigen::VectorXd::Zero(std::max(0, m - 1));
  for (int k = 0; k + 1 < m; ++k) off[k] = beta[k];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off, Eigen::EigenvaluesOnly);
  return solver.eigenvalues().maxCoeff();
}

}  // namespace

double highestFrequency(const mysim::Model& model) {
  const MassNormalisedStiffness op(model);
  if (op.size() == 0 || model.springs.empty()) return 0.0;
  return std::sqrt(std::max(0.0, largestEigenvalue(op)));
}

}  // namespace springcheck
