#pragma once
#include "mysim/model.h"

namespace springcheck {

// The highest natural frequency w_max (rad/s) of a model linearised at its start state: the
// square root of the largest eigenvalue of M^-1 K over the free particles' coordinates, K the
// springs' stiffness matrix there (elastic term, compressive part clamped, as backward Euler
// uses it). Explicit methods are stable for h w_max below a constant of the method (2 for
// symplectic Euler and Verlet, 2 sqrt 2 for RK4), which makes it the theory line of a scene's
// stability map. Lanczos on the symmetric M^-1/2 K M^-1/2, started from a seeded vector: the
// same model gives the same number. 0 when nothing is free or no spring acts.
double highestFrequency(const mysim::Model& model);

}  // namespace springcheck
