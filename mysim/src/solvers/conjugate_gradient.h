#pragma once
#include <functional>

#include "mysim/types.h"

namespace mysim {

struct CgResult {
  int iterations = 0;
  bool converged = false;
};

// y = A x for a symmetric positive definite A, given as a function so that A need not be
// assembled (backward Euler applies its per-spring blocks directly).
using LinearOperator = std::function<void(const Vector& x, Vector& y)>;

// z = P^-1 r for a symmetric positive definite preconditioner P.
using Preconditioner = std::function<void(const Vector& r, Vector& z)>;

// Preconditioned conjugate gradient from the starting guess in x; stops when
// |b - A x| <= tolerance |b|. Dot products are summed in fixed chunks in a fixed order, so the
// result does not depend on the number of threads.
CgResult conjugateGradient(const LinearOperator& A, const Preconditioner& precondition,
                           const Vector& b, Vector& x, double tolerance, int max_iterations);

// Summed in fixed chunks (in parallel for long vectors), added in order.
double deterministicDot(const Vector& a, const Vector& b);

}  // namespace mysim
