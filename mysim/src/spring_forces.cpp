#include "mysim/spring_forces.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace mysim {

SpringTable SpringTable::build(const std::vector<Spring>& springs) {
  SpringTable t;
  for (const Spring& s : springs) {
    t.i.push_back(s.i);
    t.j.push_back(s.j);
    t.rest.push_back(s.rest_length);
    t.stiffness.push_back(s.stiffness);
    t.damping.push_back(s.damping);
    t.damped |= s.damping != 0.0;
  }
  return t;
}

namespace {

// The loop both kernels compile, in blocks: first each spring's end-to-end vector (and relative
// velocity) gathered into small contiguous arrays, then the arithmetic over them, which is where
// the time goes (a square root and a division a spring) and which GCC vectorises: plain arrays,
// no branch on the element, no gathers (GCC 12 does not vectorise the indexed loads), and sqrt
// without errno (this file is built with -fno-math-errno; its arguments are squared lengths).
// Same operations in the same order as the per-end loop, so the same bits.
template <bool kDamped>
inline __attribute__((always_inline)) void springLoop(const SpringTable& s, const double* x,
                                                      const double* v, double* __restrict fx,
                                                      double* __restrict fy,
                                                      double* __restrict fz, int begin, int end) {
  constexpr int kLanes = 256;  // 4 x 2 KiB of scratch: stays in L1
  alignas(64) double dx[kLanes], dy[kLanes], dz[kLanes], dw[kLanes];
  const int* si = s.i.data();
  const int* sj = s.j.data();
  for (int b = begin; b < end; b += kLanes) {
    const int m = std::min(kLanes, end - b);
    for (int e = 0; e < m; ++e) {
      const double* xi = x + 3 * si[b + e];
      const double* xj = x + 3 * sj[b + e];
      dx[e] = xj[0] - xi[0];
      dy[e] = xj[1] - xi[1];
      dz[e] = xj[2] - xi[2];
      if constexpr (kDamped) {
        const double* vi = v + 3 * si[b + e];
        const double* vj = v + 3 * sj[b + e];
        dw[e] = dx[e] * (vj[0] - vi[0]) + dy[e] * (vj[1] - vi[1]) + dz[e] * (vj[2] - vi[2]);
      }
    }
    const double* __restrict rest = s.rest.data() + b;
    const double* __restrict k = s.stiffness.data() + b;
    const double* __restrict c = s.damping.data() + b;
    double* __restrict ox = fx + b;
    double* __restrict oy = fy + b;
    double* __restrict oz = fz + b;
    for (int e = 0; e < m; ++e) {
      const double inv_l = 1.0 / std::sqrt(dx[e] * dx[e] + dy[e] * dy[e] + dz[e] * dz[e]);
      double scale = k[e] * (1.0 - rest[e] * inv_l);
      if constexpr (kDamped) scale += c[e] * dw[e] * inv_l * inv_l;
      ox[e] = scale * dx[e];
      oy[e] = scale * dy[e];
      oz[e] = scale * dz[e];
    }
  }
}

void baselineKernel(const SpringTable& s, const double* x, const double* v, double* fx,
                    double* fy, double* fz, int begin, int end) {
  if (s.damped) {
    springLoop<true>(s, x, v, fx, fy, fz, begin, end);
  } else {
    springLoop<false>(s, x, v, fx, fy, fz, begin, end);
  }
}

#if defined(__x86_64__)
__attribute__((target("avx2"))) void avx2Kernel(const SpringTable& s, const double* x,
                                                const double* v, double* fx, double* fy,
                                                double* fz, int begin, int end) {
  if (s.damped) {
    springLoop<true>(s, x, v, fx, fy, fz, begin, end);
  } else {
    springLoop<false>(s, x, v, fx, fy, fz, begin, end);
  }
}

bool cpuHasAvx2() { return __builtin_cpu_supports("avx2"); }
#else
void avx2Kernel(const SpringTable& s, const double* x, const double* v, double* fx, double* fy,
                double* fz, int begin, int end) {
  baselineKernel(s, x, v, fx, fy, fz, begin, end);
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

void springForces(const SpringTable& springs, const double* x, const double* v, double* fx,
                  double* fy, double* fz, int begin, int end) {
  (simdEnabled() ? avx2Kernel : baselineKernel)(springs, x, v, fx, fy, fz, begin, end);
}

const char* springForcesKernel() { return simdEnabled() ? "avx2" : "baseline"; }

void setSpringForcesSimd(bool enabled) { simdEnabled() = enabled && cpuHasAvx2(); }

}  // namespace mysim
