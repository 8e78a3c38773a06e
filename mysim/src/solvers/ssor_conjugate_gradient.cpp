#include "solvers/ssor_conjugate_gradient.h"

#include <algorithm>
#include <cmath>

namespace mysim {

namespace {

// ap = F^-1 A F^-T p, the transformed system's product by Eisenstat's trick: with t = F^-T p,
// F^-1 A F^-T p = t + F^-1 (p + K t), two triangular sweeps and a diagonal scaling, no product.
// t and q are workspace.
void transformedProduct(const SpringBlockMatrix& A, const Vector& p, double k_scale, Vector& t,
                        Vector& q, Vector& ap) {
  A.solveUpper(p, t);
  A.multiplyDiagonal(t, q, k_scale);
  q += p;
  A.solveLower(q, ap);
  ap += t;
}

}  // namespace

CgResult ssorConjugateGradient(const SpringBlockMatrix& A, const Vector& b, Vector& x,
                               double tolerance, int max_iterations) {
  const double w = A.ssorOmega();
  CgResult result;
  const double b_norm = std::sqrt(deterministicDot(b, b));
  if (b_norm == 0.0) {  // A x = 0: x = 0
    x.setZero();
    result.converged = true;
    return result;
  }
  // The floor of conjugateGradient(), for the same reason (a system decaying to subnormals).
  const double threshold = std::max(tolerance * b_norm, 1e-150);
  const double k_scale = 1.0 - 2.0 / w;  // K = k_scale D

  // The start's true residual r = b - A x (a parallel product), then the transformed system:
  // r^ = F^-1 r (one sweep) and x^ = F^T x (half a product; F^-T x^ is x itself).
  Vector r, x_hat, r_hat, z, p, t, q, ap;
  A.multiply(x, r);
  r = b - r;
  const double r_norm = std::sqrt(deterministicDot(r, r));
  if (r_norm <= threshold) {
    result.converged = true;
    return result;
  }
  A.solveLower(r, r_hat);
  A.multiplyUpper(x, x_hat);
  // The true residual, F r^, costs half a product: it is checked from the iteration where r^
  // has shrunk by the factor the true residual must, and at every one after.
  const double trigger = std::sqrt(deterministicDot(r_hat, r_hat)) * (threshold / r_norm);
  bool check_true_residual = false;

  A.multiplyDiagonal(r_hat, z, 1.0 / w);
  p = z;
  double rz = deterministicDot(r_hat, z);
  for (int k = 1; k <= max_iterations; ++k) {
    transformedProduct(A, p, k_scale, t, q, ap);
    const double pAp = deterministicDot(p, ap);
    if (!(pAp > 0.0)) break;  // breakdown (not positive definite, or no progress left)
    const double alpha = rz / pAp;
    x_hat += alpha * p;
    r_hat -= alpha * ap;
    result.iterations = k;
    if (check_true_residual || std::sqrt(deterministicDot(r_hat, r_hat)) <= trigger) {
      check_true_residual = true;
      A.multiplyLower(r_hat, r);
      if (std::sqrt(deterministicDot(r, r)) <= threshold) {
        result.converged = true;
        break;
      }
    }
    A.multiplyDiagonal(r_hat, z, 1.0 / w);
    const double rz_next = deterministicDot(r_hat, z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  A.solveUpper(x_hat, x);  // x = F^-T x^
  return result;
}

}  // namespace mysim
