#include "solvers/sparse_ldlt3.h"

namespace mysim {

bool SparseLdlt3::factor(const Eigen::SparseMatrix<double>& a, std::string& error) {
  ldlt_.reset();  // the last factor is freed first: two at once would double the peak
  diagonal_.clear();
  ldlt_ = std::make_unique<Factor>(a);
  const auto refuse = [&](const char* why) {
    ldlt_.reset();
    error = why;
    return false;
  };
  if (ldlt_->info() != Eigen::Success || (ldlt_->vectorD().array() <= 0.0).any()) {
    return refuse("the matrix is not positive definite");
  }
  const Eigen::SparseMatrix<double>& l = lower();
  const int n = static_cast<int>(a.rows());
  if (!l.isCompressed()) {
    return refuse("the factor is not stored compressed");
  }
  // The sweeps below take every stored entry as strictly below the diagonal, as Eigen's LDL^T
  // stores L (its unit diagonal implied); a later Eigen that stored it would be caught here.
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(l, j); it; ++it) {
      if (it.row() <= j) {
        return refuse("the factor stores entries on or above its diagonal");
      }
    }
  }
  const Vector d = ldlt_->vectorD();  // returned by value
  diagonal_.assign(d.data(), d.data() + n);
  // Eigen leaves P empty when the ordering is the identity.
  const auto& p = ldlt_->permutationP().indices();
  permutation_.resize(n);
  for (int i = 0; i < n; ++i) permutation_[i] = p.size() == n ? p[i] : i;
  permuted_.resize(3 * n);
  return true;
}

void SparseLdlt3::solve(Vector& b) const {
  const int n = size();
  const Eigen::SparseMatrix<double>& l = lower();
  const int* column_start = l.outerIndexPtr();  // compressed: column j is [start[j], start[j+1])
  const int* rows = l.innerIndexPtr();
  const double* values = l.valuePtr();
  double* w = permuted_.data();
  for (int i = 0; i < n; ++i) {
    const int to = permutation_[i];
    w[3 * to] = b[3 * i], w[3 * to + 1] = b[3 * i + 1], w[3 * to + 2] = b[3 * i + 2];
  }
  // L w' = w, column by column (w_j is final once reached).
  for (int j = 0; j < n; ++j) {
    const double wx = w[3 * j], wy = w[3 * j + 1], wz = w[3 * j + 2];
    for (int e = column_start[j]; e < column_start[j + 1]; ++e) {
      double* wi = w + 3 * rows[e];
      const double lij = values[e];
      wi[0] -= lij * wx, wi[1] -= lij * wy, wi[2] -= lij * wz;
    }
  }
  for (int j = 0; j < n; ++j) {
    const double inverse = 1.0 / diagonal_[j];
    w[3 * j] *= inverse, w[3 * j + 1] *= inverse, w[3 * j + 2] *= inverse;
  }
  // L^T u = w', last row first: row j of L^T is column j of L.
  for (int j = n - 1; j >= 0; --j) {
    double sx = w[3 * j], sy = w[3 * j + 1], sz = w[3 * j + 2];
    for (int e = column_start[j]; e < column_start[j + 1]; ++e) {
      const double* wi = w + 3 * rows[e];
      const double lij = values[e];
      sx -= lij * wi[0], sy -= lij * wi[1], sz -= lij * wi[2];
    }
    w[3 * j] = sx, w[3 * j + 1] = sy, w[3 * j + 2] = sz;
  }
  for (int i = 0; i < n; ++i) {
    const int from = permutation_[i];
    b[3 * i] = w[3 * from], b[3 * i + 1] = w[3 * from + 1], b[3 * i + 2] = w[3 * from + 2];
  }
}

}  // namespace mysim
