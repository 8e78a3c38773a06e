#include "mysim/conjugate_gradient.h"

#include <cmath>
#include <vector>

namespace mysim {
namespace {
constexpr int kParallelEntries = 12000;
constexpr int kChunk = 4096;
}  // namespace

double deterministicDot(const Vector& a, const Vector& b) {
  const int n = static_cast<int>(a.size());
  const int chunks = (n + kChunk - 1) / kChunk;
  std::vector<double> partial(chunks);
#pragma omp parallel for schedule(static) if (n >= kParallelEntries)
  for (int c = 0; c < chunks; ++c) {
    const int begin = c * kChunk, end = std::min(n, begin + kChunk);
    partial[c] = a.segment(begin, end - begin).dot(b.segment(begin, end - begin));
  }
  double sum = 0.0;
  for (double p : partial) sum += p;
  return sum;
}

CgResult conjugateGradient(const LinearOperator& A, const Vector& inverse_diagonal, const Vector& b,
                           Vector& x, double tolerance, int max_iterations) {
  const int n = static_cast<int>(b.size());
  Vector r(n), z(n), p(n), Ap(n);
  A(x, Ap);
  r = b - Ap;
  const double b_norm = std::sqrt(deterministicDot(b, b));
  const double threshold = tolerance * (b_norm > 0.0 ? b_norm : 1.0);
  CgResult result;
  if (std::sqrt(deterministicDot(r, r)) <= threshold) {
    result.converged = true;
    return result;
  }
  z = inverse_diagonal.cwiseProduct(r);
  p = z;
  double rz = deterministicDot(r, z);
  for (int k = 1; k <= max_iterations; ++k) {
    A(p, Ap);
    const double alpha = rz / deterministicDot(p, Ap);
    x += alpha * p;
    r -= alpha * Ap;
    result.iterations = k;
    if (std::sqrt(deterministicDot(r, r)) <= threshold) {
      result.converged = true;
      return result;
    }
    z = inverse_diagonal.cwiseProduct(r);
    const double rz_next = deterministicDot(r, z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return result;
}

}  // namespace mysim
