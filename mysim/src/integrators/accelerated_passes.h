#pragma once
// The pass loop local/global and vertex block descent share: `pass` (one sweep over the system,
// updating x) runs until the control stops it (pass_control.h), its residual measured by
// implicitEulerPassResidual. With a tolerance the floor's passes run plain and Chebyshev takes
// over after them: a step done by then (small steps, soft springs) is not slowed by a rho above
// its own; without one, Chebyshev acts from the first pass (Chen 2024, the fixed-count form).
#include "integrators/implicit_euler_step.h"
#include "integrators/chebyshev.h"
#include "integrators/pass_control.h"

namespace mysim {

struct PassesRun {
  int passes = 0;
  bool converged = true;  // reached the tolerance (always, without one)
};

template <typename Pass>
PassesRun runAcceleratedPasses(const PassControl& control, ChebyshevAcceleration& chebyshev,
                               const ParticleSystem& ps, const ImplicitEulerStep& step, Vector& x,
                               Vector& residual_scratch, Pass pass) {
  int passes = 0;
  PassResidual measured;
  const int plain = control.adaptive() ? control.iterations : 0;
  do {
    const bool accelerated = chebyshev.enabled() && passes >= plain;
    if (accelerated) chebyshev.beforePass(x);
    pass();
    if (accelerated) chebyshev.afterPass(passes - plain, x);
    ++passes;
    if (control.checksAfter(passes)) measured = implicitEulerPassResidual(ps, step, x, residual_scratch);
  } while (!control.stopAfter(passes, measured.residual, measured.forces, measured.round_off));
  return {passes, control.reachedTolerance(measured.residual, measured.forces, measured.round_off)};
}

}  // namespace mysim
