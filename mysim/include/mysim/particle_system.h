#pragma once
#include <Eigen/SparseCore>

#include "mysim/blowup.h"
#include "mysim/model.h"
#include "mysim/ode_system.h"

namespace mysim {

// Particles with mass under the model's force terms. y = [x (3N); v (3N)].
// Pinned particles do not integrate forces: they follow the pin motion (or stay put).
class ParticleSystem final : public OdeSystem {
 public:
  ParticleSystem(Model model, BlowUpLimits limits);

  const Model& model() const { return model_; }
  int particleCount() const { return model_.particleCount(); }

  int dimension() const override { return 6 * particleCount(); }
  void derivative(double t, const Vector& y, Vector& dydt) override;
  void afterStep(State& state) override;
  ParticleSystem* particles() override { return this; }
  std::optional<Unhealthy> checkHealth(const State& state) const override;
  std::optional<EnergyTerms> energy(const State& state) const override;
  Eigen::Matrix<double, Eigen::Dynamic, 6> particleRows(const State& state) override;

  State initialState() const;

  // Total force on every particle (3N), pinned rows included (they are ignored by the caller).
  void force(double t, const Vector& x, const Vector& v, Vector& f) const;
  // a = f / m for free particles, the prescribed acceleration for pinned ones.
  void acceleration(double t, const Vector& x, const Vector& v, Vector& a) const;

  // Position, velocity and acceleration a pinned particle must have at time t.
  Vec3 pinPosition(int particle, double t) const;
  Vec3 pinVelocity(double t) const;

  // Largest |l / rest - 1| over all springs.
  double maxStrain(const Vector& x) const;

 private:
  void afterStepConst(State& state) const;

  Model model_;
  BlowUpLimits limits_;
  double energy_scale_ = 0.0;  // J, see the constructor
  Vector x_scratch_, v_scratch_, a_scratch_;  // (3N) derivative() workspace, allocated once
};

}  // namespace mysim
