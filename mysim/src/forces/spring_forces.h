#pragma once
#include <vector>

#include "mysim/spring.h"

namespace mysim {

// The per-spring half of the force evaluation: every spring's scalar
//   scale_s = k (1 - rest / l) + c (d . w) / l^2,   d = x_j - x_i, w = v_j - v_i, l = |d|,
// once per spring (a per-end loop computes it twice), for springs [begin, end), into `scale`
// (size S). The force on i is scale_s (x_j - x_i) and on j scale_s (x_i - x_j): ParticleSystem
// gathers them per particle through the adjacency in a fixed order, so results do not depend on
// the thread count and equal the per-end loop's to the bit (the scale is the same from either
// end: the squares and the product d . w do not change sign).
//
// Runtime dispatch: the loop is compiled twice, for AVX2 (four springs a step) and for the
// baseline x86-64 every machine has (two), and the AVX2 one runs where the CPU reports it. Both
// do the same IEEE operations in the same order (no fused multiply-add), so they give the same
// bits. `damped`: whether any spring has damping (else velocities are not read).
void springScales(const std::vector<Spring>& springs, bool damped, const double* x, const double* v,
                  double* scale, int begin, int end);

// "avx2" or "baseline": which compilation springScales runs.
const char* springForcesKernel();
// Turns the AVX2 kernel off (tests compare both; SPRINGCHECK_SIMD=0 does the same at start-up).
void setSpringForcesSimd(bool enabled);

}  // namespace mysim
