#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>

#include "mysim/energy_terms.h"
#include "mysim/state.h"

namespace mysim {

class ParticleSystem;

// An ODE y' = f(t, y). The integrators see only this.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;

  virtual int dimension() const = 0;

  // The state a run starts from (pins and constraints already applied).
  virtual State initialState() const = 0;

  // f(t, y) of the GIVEN state, never of a stored one: the trapezoidal rule and every RK stage
  // evaluate it at trial states.
  virtual void derivative(double t, const Vector& y, Vector& dydt) = 0;

  // Constraints that are not forces (exact pin positions, the collider), applied once an
  // integrator has accepted a step.
  virtual void afterStep(State& /*state*/) {}

  // Second-order integrators (symplectic Euler, Verlet, backward Euler) need x' = v, v' = a
  // structure; systems without it return null.
  virtual ParticleSystem* particles() { return nullptr; }

  // Null when the state is healthy, else which check failed and why.
  struct Unhealthy {
    std::string check;
    std::string detail;
  };
  virtual std::optional<Unhealthy> checkHealth(const State& state) const = 0;

  // How far, in J, the total energy of a passive system may rise above its lowest earlier value
  // before the run counts as unstable; none for systems without energy or with external drivers.
  virtual std::optional<double> energyRiseLimit() const { return std::nullopt; }

  // Energy terms where the system has them.
  virtual std::optional<EnergyTerms> energy(const State& state) const = 0;

  // Whether anything drives the system from outside (wind, moving pins); only then is work
  // tracked, with externalWork() over each step.
  virtual bool hasExternalDriver() const { return false; }
  // Work done on the system by its external drivers from `before` to `after` (one step), J.
  virtual double externalWork(const State& /*before*/, const State& /*after*/) const { return 0.0; }

  // Rows (x, y, z, vx, vy, vz), one per particle, for output.
  virtual Eigen::Matrix<double, Eigen::Dynamic, 6> particleRows(const State& state) = 0;
};

}  // namespace mysim
