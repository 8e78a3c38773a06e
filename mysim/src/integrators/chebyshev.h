#pragma once
// Chebyshev semi-iterative acceleration of a linearly converging fixed-point iteration (Wang,
// "A Chebyshev semi-iterative approach for accelerating projective and position-based dynamics",
// 2015; Chen et al. 2024 use it for VBD): after each whole pass x_n, the iterate is pushed to
//   x_n <- omega_n (x_n - x_{n-2}) + x_{n-2},
//   omega_1 = 1, omega_2 = 2 / (2 - rho^2), omega_n = 4 / (4 - rho^2 omega_{n-1}),
// where rho estimates the plain iteration's spectral radius (its rate per pass). An estimate
// below the true rate gains less; one above it overshoots (measured in the catalogue).
// rho = 0 is the plain iteration. Pinned entries, equal in every iterate, stay where they are.
#include "mysim/types.h"

namespace mysim {

class ChebyshevAcceleration {
 public:
  explicit ChebyshevAcceleration(double rho) : rho_(rho) {}
  bool enabled() const { return rho_ > 0.0; }

  // Before pass `it` of the accelerated run (0 for its first): the iterate it starts from.
  void beforePass(const Vector& x) { previous_ = x; }

  // After pass `it`: x pushed past the pass's own result; omega carries from pass to pass.
  void afterPass(int it, Vector& x) {
    if (it == 0) {
      omega_ = 1.0;
    } else if (it == 1) {
      omega_ = 2.0 / (2.0 - rho_ * rho_);
    } else {
      omega_ = 4.0 / (4.0 - rho_ * rho_ * omega_);
    }
    if (it >= 1) x = omega_ * (x - before_previous_) + before_previous_;
    before_previous_ = previous_;
  }

 private:
  double rho_;
  double omega_ = 1.0;
  Vector previous_, before_previous_;  // iterates one and two passes back
};

}  // namespace mysim
