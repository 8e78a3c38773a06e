#pragma once
// The local/global matrix of the n x n benchmark cloth at h = 1/60 s: the solver's own
// (integrators/local_global_matrix.h), lower triangle, pins eliminated.
#include <Eigen/SparseCore>

#include "bench_scenes.h"
#include "integrators/local_global_matrix.h"
#include "mysim/scene.h"

namespace bench {

constexpr double kLargeStep = 1.0 / 60.0;

inline Eigen::SparseMatrix<double> localGlobalMatrix(int n) {
  const mysim::Scene scene = hangingCloth(n, "local-global", kLargeStep);
  return mysim::localGlobalMatrix(mysim::buildModel(scene), kLargeStep).lower;
}

}  // namespace bench
