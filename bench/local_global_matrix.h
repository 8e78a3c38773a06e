#pragma once
// The local/global matrix of the n x n benchmark cloth at h = 1/60 s, as local_global.cpp
// assembles it: masses (with drag) over h^2 plus the springs' Laplacian, pins eliminated.
#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "bench_scenes.h"
#include "mysim/model.h"
#include "mysim/scene.h"

namespace bench {

constexpr double kLargeStep = 1.0 / 60.0;

inline Eigen::SparseMatrix<double> localGlobalMatrix(int n) {
  const mysim::Scene scene = hangingCloth(n, "local-global", kLargeStep);
  const mysim::Model model = mysim::buildModel(scene);
  std::vector<int> index(model.particleCount(), -1);
  int unknowns = 0;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (!model.pinned[p]) index[p] = unknowns++;
  }
  std::vector<Eigen::Triplet<double>> entries;
  const double h2 = kLargeStep * kLargeStep;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (index[p] >= 0) entries.emplace_back(index[p], index[p], (model.mass[p] + kLargeStep * model.drag) / h2);
  }
  for (const mysim::Spring& sp : model.springs) {
    const int a = index[sp.i], b = index[sp.j];
    if (a >= 0) entries.emplace_back(a, a, sp.stiffness);
    if (b >= 0) entries.emplace_back(b, b, sp.stiffness);
    if (a >= 0 && b >= 0) entries.emplace_back(std::max(a, b), std::min(a, b), -sp.stiffness);
  }
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

}  // namespace bench
