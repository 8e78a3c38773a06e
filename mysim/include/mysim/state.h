#pragma once
#include "mysim/types.h"

namespace mysim {

// All an integrator changes. For a particle system y = [x (3N); v (3N)]: positions of every
// particle, then velocities. For a first-order system (the circle) y is its unknowns.
struct State {
  double t = 0.0;
  Vector y;
};

}  // namespace mysim
