#pragma once
#include <Eigen/SparseCore>
#include <memory>

#include "mysim/blowup.h"
#include "mysim/hinge.h"
#include "mysim/model.h"
#include "mysim/ode_system.h"
#include "mysim/self_collision.h"
#include "mysim/spring_adjacency.h"

namespace mysim {

// Particles with mass under the model's force terms. y = [x (3N); v (3N)].
// Pinned particles do not integrate forces: they follow the pin motion (or stay put).
// The model is shared, never changed: a system copies a Model it is given, takes a temporary
// over, and shares one given by pointer; borrowed() lends one without a copy (a copy of a
// 512 x 512 cloth's model holds 20 MB of per-node arrays; its springs are shared copy-on-write
// anyway) to a system its owner outlives, as an engine's instance its registry's model.
class ParticleSystem final : public OdeSystem {
 public:
  ParticleSystem(const Model& model, BlowUpLimits limits)
      : ParticleSystem(std::make_shared<const Model>(model), limits) {}
  ParticleSystem(Model&& model, BlowUpLimits limits)
      : ParticleSystem(std::make_shared<const Model>(std::move(model)), limits) {}
  ParticleSystem(std::shared_ptr<const Model> model, BlowUpLimits limits);

  const Model& model() const { return model_; }
  int particleCount() const { return model_.particleCount(); }

  int dimension() const override { return 6 * particleCount(); }
  void derivative(double t, const Vector& y, Vector& dydt) override;
  void afterStep(State& state) override;
  ParticleSystem* particles() override { return this; }
  std::optional<Unhealthy> checkHealth(const State& state) const override;
  std::optional<EnergyTerms> energy(const State& state) const override;
  bool hasExternalDriver() const override { return model_.wind || model_.pin_motion; }
  std::optional<double> energyRiseLimit() const override {
    if (hasExternalDriver()) return std::nullopt;
    return (model_.drag > 0.0 ? limits_.max_energy_rise_damped : limits_.max_energy_rise) *
           energy_scale_;
  }
  // Wind: its force is constant within a gust window, so over a step inside one window the work
  // is exactly F . (x_after - x_before) (evaluated at the step's midpoint time). Moving pins:
  // the trapezoidal rule on their power -sum F_springs_on_pin . v_pin.
  double externalWork(const State& before, const State& after) const override;
  Eigen::Matrix<double, Eigen::Dynamic, 6> particleRows(const State& state) override;

  State initialState() const override;

  // Total force on every particle (3N), pinned rows included (they are ignored by the caller).
  // `f` must have size 3N. Every spring's force scale once (spring_forces.h, vectorised), then
  // gathered per particle from the spring adjacency, both in parallel (OpenMP) when there are
  // enough particles to pay for the threads; the result does not depend on the thread count.
  // Not for two threads at once on one system: the spring pass writes a scratch array.
  void force(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
             Eigen::Ref<Vector> f) const;
  // The same force by the plain per-end loop (each spring evaluated from both of its ends, one
  // particle at a time): the reference the fast path is tested against.
  void referenceForce(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                      Eigen::Ref<Vector> f) const;
  // a = f / m for free particles, the prescribed acceleration for pinned ones. `a`: size 3N.
  void acceleration(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                    Eigen::Ref<Vector> a) const;
  const SpringAdjacency& adjacency() const { return adjacency_; }
  const HingeAdjacency& hingeAdjacency() const { return hinge_adjacency_; }
  // Gravity, drag and wind on particle p at time t (v: the 3N velocities): every force but the
  // springs', what both force loops start each sum from.
  Vec3 externalForce(int p, double t, const double* v) const;

  // Position, velocity and acceleration a pinned particle must have at time t.
  Vec3 pinPosition(int particle, double t) const;
  Vec3 pinVelocity(double t) const;

  bool hasSelfCollision() const { return self_collision_.has_value(); }
  // Self-collision's pass (self_collision.h) on positions x and velocities v of a step that
  // began at `start`, as afterStep runs it before the colliders'; nothing without it.
  void selfContactPass(Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x,
                       Eigen::Ref<Vector> v) const;

  // Largest |l / rest - 1| over all springs.
  double maxStrain(Eigen::Ref<const Vector> x) const;

 private:
  void afterStepConst(State& state) const;
  double pinPower(const State& state) const;
  // The force loop; with `accelerations`, divided by mass (pinned: the prescribed acceleration)
  // in the same pass.
  void gather(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
              Eigen::Ref<Vector> out, bool accelerations) const;
  // Particle p's force: its external force, then its springs (from their scales) and hinges
  // (from their k b) in the adjacencies' fixed order.
  Vec3 particleForce(int p, double t, const double* xs, const double* vs) const;

  std::shared_ptr<const Model> shared_model_;  // owns nothing when borrowed (model.h)
  const Model& model_;                         // *shared_model_
  BlowUpLimits limits_;
  // Positions (and time) after the last contact pass: where the next step began, which
  // friction measures the step's slide from. Mutable: initialState(), const, starts them.
  mutable Vector step_start_;
  mutable double step_start_t_ = 0.0;
  mutable std::optional<SelfCollision> self_collision_;  // when the model asks for it
  double energy_scale_ = 0.0;    // J, see the constructor
  SpringAdjacency adjacency_;    // derived from model_.springs once
  bool damped_springs_ = false;  // any spring damping: the per-spring pass reads velocities
  mutable Vector spring_scale_;  // (S) each spring's force scale: scratch of gather()
  HingeAdjacency hinge_adjacency_;
  mutable Vector hinge_force_;   // (3H) each hinge's k b: scratch of gather()
  void gatherPerEnd(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                    Eigen::Ref<Vector> out) const;
};

}  // namespace mysim
