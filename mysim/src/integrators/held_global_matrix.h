#pragma once
// Local/global's global step with particles held on a collider (integrators/contact_holds.h). A
// hold keeps the particle on the surface's tangent plane, free along it; as a quadratic term of the
// step's energy it is a stiff spring to the plane, K/2 (n . (x - point))^2, with K kHoldWeight
// times the particle's own diagonal entry, so the plane is kept to a millionth of the particle's
// move. Its matrix K n n^T couples the particle's x, y and z, which the constant matrix keeps
// apart, so the step's matrix is factored as one 3F x 3F matrix (Eigen's SimplicialLDLT), once per
// round of holds that differ from the few factored last (a resting cloth on a plane keeps its
// factors from step to step): contact scenes pay for it, the others nothing.
#include <Eigen/SparseCholesky>
#include <memory>
#include <vector>

#include "integrators/contact_holds.h"

namespace mysim {

class HeldGlobalMatrix {
 public:
  // `lower`: the constant matrix (F x F, lower triangle; local_global_matrix.h), `free_index`
  // each particle's unknown. False if the factorisation fails.
  bool factor(const Eigen::SparseMatrix<double>& lower, const std::vector<int>& free_index,
              const ContactHolds& holds);
  // The constant matrix changed (another step size): the next factor() factors anew.
  void forget();
  // The holds' right-hand side, K (n . point) n on each held unknown.
  void addHoldTerms(Vector& rhs) const;
  // Solves in place (rhs by unknown, x y z).
  void solve(Vector& rhs) const;

 private:
  static constexpr double kHoldWeight = 1e6;
  struct Term {
    int unknown;
    double weight;  // K
    bool whole;     // held at the point: K I, not K n n^T
    Vec3 normal, point;
  };
  using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>;
  struct Factored {
    std::vector<Term> terms;
    std::unique_ptr<Factor> factor;
  };
  static constexpr std::size_t kRecent = 4;  // factors kept: a step's rounds, and the last step's
  std::vector<Term> terms_;   // this round's holds
  std::vector<Factored> recent_;
  const Factor* current_ = nullptr;  // this round's, in recent_
};

}  // namespace mysim
