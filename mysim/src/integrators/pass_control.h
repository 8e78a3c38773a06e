#pragma once
// When an iterative step solver (XPBD, local/global, vertex block descent) stops passing over
// the system. A fixed number of passes is no guarantee: on stiff springs at large steps
// (h^2 k / m in the hundreds) ten passes leave most of the step unsolved, and an unsolved
// implicit step can gain energy and blow up (measured: docs/performance.md "Passes to a
// tolerance"). So after the `iterations` passes that always run, the solver goes on until its
// residual is at most `tolerance` times the forces acting (the largest of the step's load, its
// inertial term and the springs' and hinges' forces: implicitEulerPassResidual, or XPBD's own
// measure), or `max_iterations` passes; a step that stops at the cap counts a solver failure (the
// run reports it, as backward Euler's CG).
// tolerance 0 runs exactly `iterations` passes (the fixed-count form, for comparison).
#include <algorithm>

#include "mysim/integrator.h"

namespace mysim {

struct PassControl {
  int iterations = 10;
  int max_iterations = 10;
  double tolerance = 0.0;

  static PassControl from(const IntegratorSettings& s) {
    PassControl c;
    c.iterations = static_cast<int>(s.value("iterations"));
    c.tolerance = s.value("tolerance");
    c.max_iterations = std::max(c.iterations, static_cast<int>(s.value("max_iterations")));
    return c;
  }
  bool adaptive() const { return tolerance > 0.0; }
  // Whether the residual needs measuring after pass `done` (1-based).
  bool checksAfter(int done) const { return adaptive() && done >= iterations; }
  // After pass `done`: whether to stop, given the residual (when checksAfter), its reference and
  // the residual's round-off floor (a residual at it is as solved as the arithmetic allows).
  bool stopAfter(int done, double residual, double reference, double floor = 0.0) const {
    if (done < iterations) return false;
    if (!adaptive()) return true;
    return reachedTolerance(residual, reference, floor) || done >= max_iterations;
  }
  bool reachedTolerance(double residual, double reference, double floor = 0.0) const {
    return !adaptive() || residual <= std::max(tolerance * reference, floor);
  }
};

}  // namespace mysim
