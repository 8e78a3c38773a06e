#pragma once
#include <vector>

#include "mysim/spring.h"

namespace mysim {

// The springs as plain arrays, for the force pass that computes every spring's force once
// (a per-end gather computes it twice) in a loop the compiler vectorises. ParticleSystem then
// gathers each particle's forces from its springs' results through the adjacency
// (spring_adjacency.h), in a fixed order: results do not depend on the thread count, and they
// equal the per-end reference loop to the bit (the force on j is exactly minus the force on i).
struct SpringTable {
  std::vector<int> i, j;                       // (S) ends
  std::vector<double> rest, stiffness, damping;  // (S)
  bool damped = false;                         // any damping: the pass then reads velocities

  static SpringTable build(const std::vector<Spring>& springs);
  int size() const { return static_cast<int>(i.size()); }
};

// f_s = [k (1 - rest / l) + c (d . w) / l^2] d, d = x_j - x_i, w = v_j - v_i: the force on end i
// of springs [begin, end), into fx, fy, fz (each of size S).
//
// Runtime dispatch: the same loop is compiled twice, for AVX2 (four springs a step) and for the
// baseline x86-64 every machine has, and the AVX2 one runs where the CPU reports it. Both do the
// same IEEE operations in the same order (no fused multiply-add), so they give the same bits.
void springForces(const SpringTable& springs, const double* x, const double* v, double* fx,
                  double* fy, double* fz, int begin, int end);

// "avx2" or "baseline": which compilation springForces runs.
const char* springForcesKernel();
// Turns the AVX2 kernel off (tests compare both; SPRINGCHECK_SIMD=0 does the same at start-up).
void setSpringForcesSimd(bool enabled);

}  // namespace mysim
