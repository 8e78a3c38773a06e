#pragma once
// The numbers a model is made of must be ones double precision can step: every mass, stiffness,
// damping, drag, gravity, rest length and the step (and every coordinate from above) between kSmallestScale and kLargestScale (when
// not 0), and a step that does not swamp the stiffest spring's inertia.
// Checked before a run, so a strip of density 1e300 (whose squared forces overflow inside the
// solver, so it "ran" with status ok and never moved) is refused, naming the field.
#include <optional>

#include "mysim/model.h"
#include "mysim/limit_error.h"

namespace mysim {

// 1e-50 .. 1e50: a product of the few quantities a solver multiplies (m g h, k x, their squares in
// a norm: (1e50 x 1e50)^2 = 1e200) stays far inside double's 1e-308 .. 1e308; no physical cloth,
// rope or particle in SI comes within 1e30 of either end.
constexpr double kSmallestScale = 1e-50;
constexpr double kLargestScale = 1e50;
// h w beyond 1e8 (h^2 w^2 > 1e16 = 1/epsilon): the mass term of the step is lost in round-off
// against the spring's, so no method integrates the motion (the stability studies go to 3e3).
constexpr double kLargestStepStiffness = 1e8;
// The step itself within the scales too. (No lower bound on h^2 k / m: a weak spring's pull still
// adds up over steps; what broke at density 1e300 was the squared forces' overflow.)
std::optional<LimitError> checkModelScales(const Model& model, double dt);

}  // namespace mysim
