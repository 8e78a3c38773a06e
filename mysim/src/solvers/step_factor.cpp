#include "solvers/step_factor.h"

namespace mysim {

bool StepFactor::factor(int n, const std::vector<Triplet>& lower) {
  matrix_.resize(n, n);
  matrix_.setFromTriplets(lower.begin(), lower.end());
  if (!ldlt_) ldlt_ = std::make_unique<Factor>();
  // The pattern holds every spring and hinge coupling, zero or not (setFromTriplets keeps
  // explicit zeros), so one ordering serves every step.
  if (!analysed_) ldlt_->analyzePattern(matrix_), analysed_ = true;
  ldlt_->factorize(matrix_);
  return ldlt_->info() == Eigen::Success && (ldlt_->vectorD().array() > 0.0).all();
}

void StepFactor::solve(const Vector& r, Vector& z) const { z = ldlt_->solve(r); }

}  // namespace mysim
