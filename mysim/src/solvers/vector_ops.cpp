#include "solvers/vector_ops.h"

namespace mysim {
namespace {
// Entries below which one thread is faster (512 particles: 3072 state entries).
constexpr long kParallelVectorLength = 3072;
}  // namespace

void addScaled(const Vector& y, double s, const Vector& k, Vector& out) {
  const long n = y.size();
  out.resize(n);
  const double* py = y.data();
  const double* pk = k.data();
  double* po = out.data();
#pragma omp parallel for simd schedule(static) if (n >= kParallelVectorLength)
  for (long i = 0; i < n; ++i) po[i] = py[i] + s * pk[i];
}

void copyParallel(Eigen::Ref<const Vector> from, Eigen::Ref<Vector> to) {
  const long n = from.size();
  const double* pf = from.data();
  double* pt = to.data();
#pragma omp parallel for simd schedule(static) if (n >= kParallelVectorLength)
  for (long i = 0; i < n; ++i) pt[i] = pf[i];
}

}  // namespace mysim
