#pragma once
#include "solvers/conjugate_gradient.h"
#include "solvers/spring_block_matrix.h"

namespace mysim {

// Conjugate gradient on A x = b preconditioned with block SSOR, P = F D^-1 w F^T where
// F = D/w + L (D the 3x3 diagonal blocks, L the strict lower block triangle), in Eisenstat's
// form (S. C. Eisenstat, "Efficient implementation of a class of preconditioned conjugate
// gradient methods", SIAM J. Sci. Stat. Comput. 2, 1981): CG runs on F^-1 A F^-T with the
// preconditioner D/w, which gives the same iterates, and since A = F + F^T + K, K = (1 - 2/w) D,
//   F^-1 A F^-T p = t + F^-1 (p + K t),   t = F^-T p,
// an iteration costs one upper and one lower sweep: half the neighbour work of a product plus
// the two sweeps of applying P^-1.
//
// Stops, as conjugateGradient() does, when |b - A x| <= tolerance |b|. The true residual is
// F times the transformed one, half a product: it is computed once the transformed residual has
// shrunk from its start by the factor the true one must, and at every iteration after. Starts
// from the guess in x.
// Sequential sweeps: the result does not depend on the number of threads.
// A: after A.prepareSsor(w).
CgResult ssorConjugateGradient(const SpringBlockMatrix& A, const Vector& b, Vector& x,
                               double tolerance, int max_iterations);

}  // namespace mysim
