#pragma once
#include "mysim/ode_system.h"

namespace mysim {

// The seed's simple system: x' = -y, y' = x. Exact solution from (1, 0): the unit circle at
// angular rate 1, so the radius measures an integrator's amplitude error directly.
class CircleSystem final : public OdeSystem {
 public:
  explicit CircleSystem(Eigen::Vector2d start) : start_(start) {}

  int dimension() const override { return 2; }
  void derivative(double t, const Vector& y, Vector& dydt) override;
  std::optional<Unhealthy> checkHealth(const State& state) const override;
  std::optional<EnergyTerms> energy(const State&) const override { return std::nullopt; }
  Eigen::Matrix<double, Eigen::Dynamic, 6> particleRows(const State& state) override;

  State initialState() const;

 private:
  Eigen::Vector2d start_;
};

}  // namespace mysim
