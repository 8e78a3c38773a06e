#pragma once
#include <Eigen/Core>

#include "mysim/types.h"

namespace mysim {

// The few whole-state vector operations an explicit step does between force evaluations, split
// across cores for large systems (Eigen runs them on one). Elementwise, so the result does not
// depend on the thread count.

// out = y + s k
void addScaled(const Vector& y, double s, const Vector& k, Vector& out);
// y += h/6 (k1 + 2 k2 + 2 k3 + k4)
void addRk4Slopes(double h, const Vector& k1, const Vector& k2, const Vector& k3, const Vector& k4,
                  Vector& y);
// to = from
void copyParallel(Eigen::Ref<const Vector> from, Eigen::Ref<Vector> to);

}  // namespace mysim
