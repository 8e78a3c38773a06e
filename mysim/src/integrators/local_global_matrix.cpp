#include "integrators/local_global_matrix.h"

#include <algorithm>

namespace mysim {

LocalGlobalMatrix localGlobalMatrix(const Model& model, double h) {
  LocalGlobalMatrix m;
  const int n = model.particleCount();
  m.free_index.assign(n, -1);
  for (int p = 0; p < n; ++p) {
    if (!model.pinned[p]) {
      m.free_index[p] = static_cast<int>(m.free_particles.size());
      m.free_particles.push_back(p);
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int p : m.free_particles) {
    const double m_eff = model.mass[p] + h * model.drag;
    entries.emplace_back(m.free_index[p], m.free_index[p], m_eff / (h * h));
  }
  m.weight.resize(static_cast<Eigen::Index>(model.springs.size()));
  for (int k = 0; k < static_cast<int>(model.springs.size()); ++k) {
    const Spring& sp = model.springs[k];
    m.weight[k] = sp.stiffness + sp.damping / h;
    const int a = m.free_index[sp.i], b = m.free_index[sp.j];
    if (a >= 0) entries.emplace_back(a, a, m.weight[k]);
    if (b >= 0) entries.emplace_back(b, b, m.weight[k]);
    if (a >= 0 && b >= 0) entries.emplace_back(std::max(a, b), std::min(a, b), -m.weight[k]);
  }
  // Hinges (hinge.h): their energy is quadratic, k w w^T per hinge, so it goes into the
  // matrix exactly and needs no local step; a pinned hinge particle's column moves to the
  // right-hand side (the solver's global step).
  for (const Hinge& hinge : model.hinges) {
    for (int a = 0; a < 4; ++a) {
      const int fa = m.free_index[hinge.particle[a]];
      if (fa < 0) continue;
      for (int c = 0; c < 4; ++c) {
        const int fc = m.free_index[hinge.particle[c]];
        if (fc < 0 || fc > fa) continue;  // the lower triangle, as the springs'
        entries.emplace_back(fa, fc, hinge.stiffness * hinge.weight[a] * hinge.weight[c]);
      }
    }
  }
  const int unknowns = static_cast<int>(m.free_particles.size());
  m.lower.resize(unknowns, unknowns);
  m.lower.setFromTriplets(entries.begin(), entries.end());
  return m;
}

}  // namespace mysim
