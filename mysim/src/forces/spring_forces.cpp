#include "forces/spring_forces.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace mysim {

namespace {

// The loop both kernels compile, in blocks: first each spring's end-to-end vector, relative
// velocity term and parameters gathered into small contiguous arrays, then the arithmetic over
// them, which is where the time goes (a square root and a division a spring) and which GCC
// vectorises: plain arrays, no branch on the element, no gathers (GCC 12 does not vectorise the
// indexed loads), and sqrt without errno (this file is built with -fno-math-errno; its arguments
// are squared lengths). The operations and their order are the per-end loop's.
template <bool kDamped>
inline __attribute__((always_inline)) void springLoop(const Spring* springs, const double* x,
                                                      const double* v, double* __restrict scale,
                                                      int begin, int end) {
  constexpr int kLanes = 256;  // 7 x 2 KiB of scratch: stays in L1
  alignas(64) double dx[kLanes], dy[kLanes], dz[kLanes], dw[kLanes], rest[kLanes], k[kLanes],
      c[kLanes];
  for (int b = begin; b < end; b += kLanes) {
    const int m = std::min(kLanes, end - b);
    for (int e = 0; e < m; ++e) {
      const Spring& s = springs[b + e];
      const double* xi = x + 3 * s.i;
      const double* xj = x + 3 * s.j;
      dx[e] = xj[0] - xi[0];
      dy[e] = xj[1] - xi[1];
      dz[e] = xj[2] - xi[2];
      rest[e] = s.rest_length;
      k[e] = s.stiffness;
      if constexpr (kDamped) {
        const double* vi = v + 3 * s.i;
        const double* vj = v + 3 * s.j;
        dw[e] = dx[e] * (vj[0] - vi[0]) + dy[e] * (vj[1] - vi[1]) + dz[e] * (vj[2] - vi[2]);
        c[e] = s.damping;
      }
    }
    double* __restrict out = scale + b;
    for (int e = 0; e < m; ++e) {
      const double inv_l = 1.0 / std::sqrt(dx[e] * dx[e] + dy[e] * dy[e] + dz[e] * dz[e]);
      double value = k[e] * (1.0 - rest[e] * inv_l);
      if constexpr (kDamped) value += c[e] * dw[e] * inv_l * inv_l;
      out[e] = value;
    }
  }
}

void baselineKernel(const std::vector<Spring>& springs, bool damped, const double* x,
                    const double* v, double* scale, int begin, int end) {
  if (damped) {
    springLoop<true>(springs.data(), x, v, scale, begin, end);
  } else {
    springLoop<false>(springs.data(), x, v, scale, begin, end);
  }
}

#if defined(__x86_64__)
__attribute__((target("avx2"))) void avx2Kernel(const std::vector<Spring>& springs, bool damped,
                                                const double* x, const double* v, double* scale,
                                                int begin, int end) {
  if (damped) {
    springLoop<true>(springs.data(), x, v, scale, begin, end);
  } else {
    springLoop<false>(springs.data(), x, v, scale, begin, end);
  }
}

bool cpuHasAvx2() { return __builtin_cpu_supports("avx2"); }
#else
void avx2Kernel(const std::vector<Spring>& springs, bool damped, const double* x, const double* v,
                double* scale, int begin, int end) {
  baselineKernel(springs, damped, x, v, scale, begin, end);
}
bool cpuHasAvx2() { return false; }
#endif

bool simdAllowed() {
  const char* env = std::getenv("SPRINGCHECK_SIMD");
  return !(env && std::strcmp(env, "0") == 0);
}

bool& simdEnabled() {
  static bool enabled = cpuHasAvx2() && simdAllowed();
  return enabled;
}

}  // namespace

void springScales(const std::vector<Spring>& springs, bool damped, const double* x, const double* v,
                  double* scale, int begin, int end) {
  (simdEnabled() ? avx2Kernel : baselineKernel)(springs, damped, x, v, scale, begin, end);
}

const char* springForcesKernel() { return simdEnabled() ? "avx2" : "baseline"; }

void setSpringForcesSimd(bool enabled) { simdEnabled() = enabled && cpuHasAvx2(); }

}  // namespace mysim
