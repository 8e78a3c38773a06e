#pragma once
// One scalar sparse SPD matrix (a node graph's: masses plus a weighted Laplacian), factored once
// as P A P^T = L D L^T with Eigen's SimplicialLDLT (AMD ordering), then applied to the x, y and z
// columns of a right-hand side together: each triangular sweep reads the factor once for all
// three, where three separate solves read it three times (the solve is bound by reading L).
// The sweeps read Eigen's own factor in place: a copy of it doubled the peak memory of a large
// cloth (the factor is most of local/global's memory: docs/performance.md "Scale").
#include <Eigen/SparseCholesky>
#include <memory>
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
  long factorNonZeros() const { return ldlt_ ? static_cast<long>(lower().nonZeros()) : 0; }

 private:
  using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower,
                                       Eigen::AMDOrdering<int>>;
  // L by columns, strictly below its unit diagonal (checked when factored).
  const Eigen::SparseMatrix<double>& lower() const { return ldlt_->matrixL().nestedExpression(); }

  std::unique_ptr<Factor> ldlt_;
  std::vector<double> diagonal_;   // (n) D
  std::vector<int> permutation_;   // (n) row i of A is row permutation_[i] of P A P^T
  mutable Vector permuted_;        // (3n) scratch
};

}  // namespace mysim
