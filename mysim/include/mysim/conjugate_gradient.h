#pragma once
#include <Eigen/SparseCore>

#include "mysim/types.h"

namespace mysim {

using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct CgResult {
  int iterations = 0;
  bool converged = false;
};

// Jacobi-preconditioned conjugate gradient for a symmetric positive definite A (both triangles
// stored), from the starting guess in x; stops when |b - A x| <= tolerance |b|.
//
// Written here rather than taken from Eigen so that (1) the matrix-vector product runs on all
// cores only when the system is large enough to pay for it (Eigen's OpenMP product spun its
// threads for most of a small cloth's step), and (2) dot products are summed in fixed chunks in a
// fixed order, so the result does not depend on the number of threads.
CgResult conjugateGradient(const RowMajorMatrix& A, const Vector& b, Vector& x, double tolerance,
                           int max_iterations);

}  // namespace mysim
