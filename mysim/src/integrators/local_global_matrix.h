#pragma once
// The constant matrix local/global factors once per scene and step (Liu et al. 2013; the solver
// is mysim/src/integrators/local_global.cpp): over the free particles,
//   M~/h^2 + sum_s (k_s + c_s/h) L_s + sum_hinges k w w^T,
// M~ the masses with drag, L_s a spring's Laplacian, pins eliminated (their terms go to the
// right-hand side). Public so the benchmarks factor the solver's own matrix.
#include <Eigen/SparseCore>
#include <vector>

#include "mysim/model.h"
#include "mysim/types.h"

namespace mysim {

struct LocalGlobalMatrix {
  std::vector<int> free_index;      // (N) each particle's unknown, -1 if pinned
  std::vector<int> free_particles;  // (F) each unknown's particle
  Vector weight;                    // (S) k + c/h: each spring's weight in the matrix
  Eigen::SparseMatrix<double> lower;  // (F x F) the matrix's lower triangle
};

LocalGlobalMatrix localGlobalMatrix(const Model& model, double h);

}  // namespace mysim
