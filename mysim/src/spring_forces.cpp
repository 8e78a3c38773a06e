#include "mysim/spring_forces.h"

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

// The loop both kernels compile. Written so GCC vectorises it (plain arrays, no branch on the
// element; this file is built with -fno-math-errno, so sqrt has no errno path).
template <bool kDamped>
inline __attribute__((always_inline)) void springLoop(const SpringTable& s, const double* x,
                                                      const double* v, double* fx, double* fy,
                                                      double* fz, int begin, int end) {
  const int* si = s.i.data();
  const int* sj = s.j.data();
  const double* rest = s.rest.data();
  const double* k = s.stiffness.data();
  const double* c = s.damping.data();
  for (int e = begin; e < end; ++e) {
    const double* xi = x + 3 * si[e];
    const double* xj = x + 3 * sj[e];
    const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
    const double inv_l = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz);
    double scale = k[e] * (1.0 - rest[e] * inv_l);
    if constexpr (kDamped) {
      const double* vi = v + 3 * si[e];
      const double* vj = v + 3 * sj[e];
      const double dw = dx * (vj[0] - vi[0]) + dy * (vj[1] - vi[1]) + dz * (vj[2] - vi[2]);
      scale += c[e] * dw * inv_l * inv_l;
    }
    fx[e] = scale * dx;
    fy[e] = scale * dy;
    fz[e] = scale * dz;
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
