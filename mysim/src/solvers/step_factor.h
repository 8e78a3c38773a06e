#pragma once
// Backward Euler's step matrix factored exactly, for its "cholesky" preconditioner: with the
// whole factor as P, preconditioned CG solves A dv = b in one iteration, a direct solve that keeps
// CG's residual check. Worth it where CG needs hundreds of iterations on a small system (a hinge
// strip's bending makes A's condition grow as the fourth power of its cells: the 64-cell
// cantilever stopped at CG's 1000-iteration cap on every step), not on a large cloth, where the
// factor's fill costs more than the iterations it saves (docs/performance.md).
#include <Eigen/SparseCholesky>
#include <memory>
#include <vector>

#include "mysim/types.h"

namespace mysim {

class StepFactor {
 public:
  using Triplet = Eigen::Triplet<double>;

  // Factors the symmetric n x n matrix whose lower triangle (diagonal included) `lower` lists
  // (repeated entries add). The first call orders the pattern (AMD); later calls must give the
  // same pattern and only refactor. False when the factor fails or is not positive definite.
  bool factor(int n, const std::vector<Triplet>& lower);
  // z = A^-1 r, after a factor that returned true.
  void solve(const Vector& r, Vector& z) const;

 private:
  using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower,
                                       Eigen::AMDOrdering<int>>;
  std::unique_ptr<Factor> ldlt_;
  Eigen::SparseMatrix<double> matrix_;
  bool analysed_ = false;
};

}  // namespace mysim
