#pragma once
#include <Eigen/Core>

#include "mysim/types.h"

namespace mysim {

// The few whole-state vector operations an explicit step does between force evaluations, split
// across cores for large systems (Eigen runs them on one). Elementwise, so the result does not
// depend on the thread count.

// out = y + s k (out may be y itself)
void addScaled(const Vector& y, double s, const Vector& k, Vector& out);
// to = from
void copyParallel(Eigen::Ref<const Vector> from, Eigen::Ref<Vector> to);

}  // namespace mysim
