#include "compare/studies/natural_frequency.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mysim/spring.h"

namespace springcheck {

double highestFrequency(const mysim::Model& model) {
  const int particles = model.particleCount();
  std::vector<int> free;  // particle of each free slot
  for (int p = 0; p < particles; ++p) {
    if (!model.pinned[p]) free.push_back(p);
  }
  const int n = 3 * static_cast<int>(free.size());
  if (n == 0 || model.springs.empty()) return 0.0;
  std::vector<int> slot(particles, -1);
  for (std::size_t s = 0; s < free.size(); ++s) slot[free[s]] = static_cast<int>(s);

  // Each spring's 3x3 block at the start state; K x sums them (K_ii = sum J, K_ij = -J).
  std::vector<mysim::Mat3> blocks;
  blocks.reserve(model.springs.size());
  const auto& x0 = model.start_position;
  for (const mysim::Spring& s : model.springs) {
    blocks.push_back(mysim::springElasticJacobianDefinite(
        x0.segment<3>(3 * s.i), x0.segment<3>(3 * s.j), s.rest_length, s.stiffness));
  }
  Eigen::VectorXd inv_sqrt_mass(n);
  for (std::size_t s = 0; s < free.size(); ++s) {
    inv_sqrt_mass.segment<3>(3 * s).setConstant(1.0 / std::sqrt(model.mass[free[s]]));
  }
  // y = M^-1/2 K M^-1/2 v on the free coordinates (pinned ones are held at zero).
  auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    const Eigen::VectorXd u = inv_sqrt_mass.cwiseProduct(v);
    y.setZero(n);
    for (std::size_t k = 0; k < model.springs.size(); ++k) {
      const int a = slot[model.springs[k].i], b = slot[model.springs[k].j];
      const mysim::Vec3 ua = a >= 0 ? mysim::Vec3(u.segment<3>(3 * a)) : mysim::Vec3::Zero();
      const mysim::Vec3 ub = b >= 0 ? mysim::Vec3(u.segment<3>(3 * b)) : mysim::Vec3::Zero();
      const mysim::Vec3 f = blocks[k] * (ua - ub);
      if (a >= 0) y.segment<3>(3 * a) += f;
      if (b >= 0) y.segment<3>(3 * b) -= f;
    }
    y = inv_sqrt_mass.cwiseProduct(y);
  };

  // Lanczos with full reorthogonalisation: the extreme Ritz value converges first, even when the
  // top of the spectrum is crowded (a cloth's is). The basis is capped at ~32 MB.
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
    apply(q, w);
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
  return std::sqrt(std::max(0.0, solver.eigenvalues().maxCoeff()));
}

}  // namespace springcheck
