#pragma once
// One scalar sparse SPD matrix (a node graph's: masses plus a weighted Laplacian), factored once
// as P A P^T = L D L^T with Eigen's SimplicialLDLT (AMD ordering), then applied to the x, y and z
// columns of a right-hand side together: each triangular sweep reads the factor once for all
// three, where three separate solves read it three times (the solve is bound by reading L).
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "mysim/types.h"

namespace mysim {

class SparseLdlt3 {
 public:
  // Factors `a` (n x n, symmetric; its lower triangle is read). Returns false, with `error` set,
  // when the matrix is not positive definite.
  bool factor(const Eigen::SparseMatrix<double>& a, std::string& error);
  // Solves A X = B for the n x 3 matrix B stored by node (b[3 i + c]); in place.
  void solve(Vector& b) const;
  int size() const { return static_cast<int>(diagonal_.size()); }
  long factorNonZeros() const { return static_cast<long>(rows_.size()); }

 private:
  std::vector<int> column_start_;  // (n + 1) L stored by columns, strictly below the diagonal
  std::vector<int> rows_;
  std::vector<double> values_;
  std::vector<double> diagonal_;   // (n) D
  std::vector<int> permutation_;   // (n) row i of A is row permutation_[i] of P A P^T
  mutable Vector permuted_;        // (3n) scratch
};

}  // namespace mysim
