#pragma once
// The nonlinear problem one implicit (backward) Euler step poses, the one every implicit solver
// family of the catalogue (local/global, vertex block descent) iterates on, so they converge to
// the same minimiser. With v1 = (x1 - x0) / h and every force taken at the step's end (t + h),
//   M (v1 - v0) = h f(t + h, x1, v1)
// over the free particles (pinned ones are on their path at t + h). Drag (-d v) is linear in v1,
// so it folds into an effective mass and target, exactly:
//   m~ = m + h d,   y~ = (m (x0 + h v0) + h d x0 + h^2 (m g + wind(t + h))) / m~,
// and the step's equations are the zero of
//   r(x) = m~ / h^2 (x - y~) + grad E_springs(x) + grad E_hinges(x)
//          + sum_s (c_s / h) u_s u_s^T (dx_i - dx_j)
// (dx = x - x0; u_s the spring's direction at x; the last term is spring damping at v1). Without
// spring damping r is the gradient of 1/(2 h^2) |x - y~|^2_M~ + E(x) (Liu et al. 2013, eq. 6).
#include "integrators/contact_holds.h"
#include "mysim/particle_system.h"
#include "mysim/state.h"

namespace mysim {

struct ImplicitEulerStep {
  double h = 0.0;
  double t_end = 0.0;
  Vector x0;              // (3N) positions at the step's start
  Vector target;          // (3N) y~ for free particles, the pin's position at t + h for pinned
  ContactHolds holds;     // the particles held on a collider (contact_holds.h)
  Vector mass_over_h2;    // (N) m~ / h^2
  double load = 0.0;      // stepLoad at t + h, summed while the target is made
};

// The step from state s by h, for system ps.
void prepareImplicitEulerStep(const ParticleSystem& ps, const State& s, double h,
                              ImplicitEulerStep& step);

// r(x) above less the kinetic friction on sliding held particles (3N, pinned rows zero): minus
// the force each particle is left with, the holds' reactions included.
void implicitEulerForces(const ParticleSystem& ps, const ImplicitEulerStep& step,
                         const Vector& x, Vector& r);
// The same with each held particle's held part removed (ContactHolds::removeReactions): the
// residual a solve drives to zero.
void implicitEulerResidual(const ParticleSystem& ps, const ImplicitEulerStep& step,
                           const Vector& x, Vector& r);

// The load the step carries: the norm over free particles of gravity and wind at t (drag, a
// reaction to motion, left out). The iterative solvers' residual is measured against it
// (pass_control.h): a force left unbalanced is small or large against the weight it holds.
double stepLoad(const ParticleSystem& ps, double t);

// An iterative solver's residual at x (pass_control.h): |r(x)|, and the forces it is held
// against, the largest of the step's load, the inertial term |m~/h^2 (x - y~)| and the springs'
// and hinges' forces: a relative residual |r| / forces is how far the forces acting on the
// particles are from balancing. (Not |r(y~)|, the residual of the prediction: at large steps
// the prediction's own stretch, h^2 g on stiff springs, is hundreds of times the weight, so a
// bound against it loosens with the step, not with anything physical.)
// `round_off`: the smallest residual the iterate can show in floating point, 64 ulps of the
// inertial term's parts (m~/h^2 |x|: r subtracts y~ from x, which costs eps |x| per particle):
// a settled scene with no load (an oscillator at rest) has forces acting that shrink toward zero,
// and a tolerance of them would ask for a residual below its own round-off.
struct PassResidual {
  double residual = 0.0;
  double forces = 0.0;
  double round_off = 0.0;
};
PassResidual implicitEulerPassResidual(const ParticleSystem& ps, const ImplicitEulerStep& step,
                                       const Vector& x, Vector& r);

// Ends the step at positions x: v = (x - x0) / h, t += h, then the system's after-step (pins on
// their path with their velocity, contacts).
void finishImplicitEulerStep(OdeSystem& system, const ImplicitEulerStep& step, const Vector& x,
                             State& s);

// One round of contact holds (contact_holds.h) on the step's result x, for a re-solve; whether
// any particle was newly held.
// `scratch`: a 3N vector for the holds' reactions.
bool holdContacts(const ParticleSystem& ps, ImplicitEulerStep& step, Vector& x, Vector& scratch);

}  // namespace mysim
