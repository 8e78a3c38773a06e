#include "mysim/vector_ops.h"

namespace mysim {
namespace {
// Entries below which one thread is faster (512 particles: 3072 state entries).
constexpr long kParallelEntries = 3072;
}  // namespace

void addScaled(const Vector& y, double s, const Vector& k, Vector& out) {
  const long n = y.size();
  out.resize(n);
  const double* py = y.data();
  const double* pk = k.data();
  double* po = out.data();
#pragma omp parallel for simd schedule(static) if (n >= kParallelEntries)
  for (long i = 0; i < n; ++i) po[i] = py[i] + s * pk[i];
}

void addRk4Slopes(double h, const Vector& k1, const Vector& k2, const Vector& k3, const Vector& k4,
                  Vector& y) {
  const long n = y.size();
  const double w = h / 6.0;
  double* py = y.data();
#pragma omp parallel for simd schedule(static) if (n >= kParallelEntries)
  for (long i = 0; i < n; ++i) py[i] += w * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

void copyParallel(Eigen::Ref<const Vector> from, Eigen::Ref<Vector> to) {
  const long n = from.size();
  const double* pf = from.data();
  double* pt = to.data();
#pragma omp parallel for simd schedule(static) if (n >= kParallelEntries)
  for (long i = 0; i < n; ++i) pt[i] = pf[i];
}

}  // namespace mysim
