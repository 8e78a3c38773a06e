#include "mysim/conjugate_gradient.h"

#include <cmath>
#include <vector>

namespace mysim {
namespace {

// Rows below which one thread is faster than two: a product over fewer rows is a few
// microseconds, about what waking the second thread costs.
constexpr int kParallelRows = 1024;
constexpr int kChunk = 4096;  // dot products: partial sums over fixed chunks, added in order

void multiply(const RowMajorMatrix& A, const Vector& x, Vector& y) {
  const int rows = static_cast<int>(A.rows());
  const int* starts = A.outerIndexPtr();
  const int* columns = A.innerIndexPtr();
  const double* values = A.valuePtr();
#pragma omp parallel for schedule(static) if (rows >= kParallelRows)
  for (int r = 0; r < rows; ++r) {
    double sum = 0.0;
    for (int k = starts[r]; k < starts[r + 1]; ++k) sum += values[k] * x[columns[k]];
    y[r] = sum;
  }
}

double dot(const Vector& a, const Vector& b) {
  const int n = static_cast<int>(a.size());
  const int chunks = (n + kChunk - 1) / kChunk;
  std::vector<double> partial(chunks);
#pragma omp parallel for schedule(static) if (n >= kParallelRows)
  for (int c = 0; c < chunks; ++c) {
    const int begin = c * kChunk, end = std::min(n, begin + kChunk);
    partial[c] = a.segment(begin, end - begin).dot(b.segment(begin, end - begin));
  }
  double sum = 0.0;
  for (double p : partial) sum += p;
  return sum;
}

}  // namespace

CgResult conjugateGradient(const RowMajorMatrix& A, const Vector& b, Vector& x, double tolerance,
                           int max_iterations) {
  const int n = static_cast<int>(b.size());
  Vector inverse_diagonal(n);
  for (int r = 0; r < n; ++r) {
    const double d = A.coeff(r, r);
    inverse_diagonal[r] = d != 0.0 ? 1.0 / d : 1.0;
  }
  Vector r(n), z(n), p(n), Ap(n);
  multiply(A, x, Ap);
  r = b - Ap;
  const double b_norm = std::sqrt(dot(b, b));
  const double threshold = tolerance * (b_norm > 0.0 ? b_norm : 1.0);
  CgResult result;
  if (std::sqrt(dot(r, r)) <= threshold) {
    result.converged = true;
    return result;
  }
  z = inverse_diagonal.cwiseProduct(r);
  p = z;
  double rz = dot(r, z);
  for (int k = 1; k <= max_iterations; ++k) {
    multiply(A, p, Ap);
    const double alpha = rz / dot(p, Ap);
    x += alpha * p;
    r -= alpha * Ap;
    result.iterations = k;
    if (std::sqrt(dot(r, r)) <= threshold) {
      result.converged = true;
      return result;
    }
    z = inverse_diagonal.cwiseProduct(r);
    const double rz_next = dot(r, z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return result;
}

}  // namespace mysim
