#include "solvers/sparse_ldlt3.h"

#include <Eigen/SparseCholesky>

namespace mysim {

bool SparseLdlt3::factor(const Eigen::SparseMatrix<double>& a, std::string& error) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(a);
  if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() <= 0.0).any()) {
    error = "the matrix is not positive definite";
    return false;
  }
  const Eigen::SparseMatrix<double>& l = ldlt.matrixL().nestedExpression();
  const int n = static_cast<int>(a.rows());
  column_start_.assign(n + 1, 0);
  rows_.clear();
  values_.clear();
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(l, j); it; ++it) {
      if (it.row() <= j) continue;  // the unit diagonal, if stored
      rows_.push_back(static_cast<int>(it.row()));
      values_.push_back(it.value());
    }
    column_start_[j + 1] = static_cast<int>(rows_.size());
  }
  const Vector d = ldlt.vectorD();  // returned by value
  diagonal_.assign(d.data(), d.data() + n);
  // Eigen leaves P empty when the ordering is the identity.
  const auto& p = ldlt.permutationP().indices();
  permutation_.resize(n);
  for (int i = 0; i < n; ++i) permutation_[i] = p.size() == n ? p[i] : i;
  permuted_.resize(3 * n);
  return true;
}

void SparseLdlt3::solve(Vector& b) const {
  const int n = size();
  double* w = permuted_.data();
  for (int i = 0; i < n; ++i) {
    const int to = permutation_[i];
    w[3 * to] = b[3 * i], w[3 * to + 1] = b[3 * i + 1], w[3 * to + 2] = b[3 * i + 2];
  }
  // L w' = w, column by column (w_j is final once reached).
  for (int j = 0; j < n; ++j) {
    const double wx = w[3 * j], wy = w[3 * j + 1], wz = w[3 * j + 2];
    for (int e = column_start_[j]; e < column_start_[j + 1]; ++e) {
      double* wi = w + 3 * rows_[e];
      const double lij = values_[e];
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
    for (int e = column_start_[j]; e < column_start_[j + 1]; ++e) {
      const double* wi = w + 3 * rows_[e];
      const double lij = values_[e];
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
