#pragma once
#include "mysim/model.h"
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
  // The mechanical twin's energy (circleTwin below) on the circle's state, where the twin's
  // velocity is (-y, x): kinetic 1/2 r^2 plus spring 1/2 r^2. It is conserved exactly by the
  // circle, so its drift is the integrator's amplitude error (forward Euler's grows by 1 + h^2
  // a step), not a zero for want of an energy.
  std::optional<EnergyTerms> energy(const State& state) const override;
  Eigen::Matrix<double, Eigen::Dynamic, 6> particleRows(const State& state) override;

  State initialState() const override;

 private:
  Eigen::Vector2d start_;
};

// The circle as a mechanical system, for engines that simulate only particles and springs: a
// unit mass on a zero-length spring of stiffness 1 from a pin at the origin (particle 0),
// started at (x0, y0, 0) with velocity (-y0, x0, 0) (particle 1). Its position obeys x'' = -x,
// whose solution from that start is the circle's, and any linear one-step method applied to it
// changes the radius by the same factor per step as on the first-order form (each coordinate is
// an oscillator whose phase point turns like the circle's).
Model circleTwin(const Model& circle);
constexpr int kCircleTwinParticle = 1;  // the particle that traces the circle

}  // namespace mysim
