#include "mysim/circle_system.h"

#include <cmath>

namespace mysim {

void CircleSystem::derivative(double /*t*/, const Vector& y, Vector& dydt) {
  dydt.resize(2);
  dydt[0] = -y[1];
  dydt[1] = y[0];
}

std::optional<OdeSystem::Unhealthy> CircleSystem::checkHealth(const State& state) const {
  if (!state.y.allFinite()) return Unhealthy{"non-finite", "state has a NaN or infinity"};
  // Forward Euler grows the radius by sqrt(1 + h^2) a step; a thousandfold growth is runaway.
  const double limit = 1e3 * start_.norm();
  if (state.y.norm() > limit) {
    return Unhealthy{"energy",
                     "radius " + std::to_string(state.y.norm()) + " > " + std::to_string(limit)};
  }
  return std::nullopt;
}

std::optional<EnergyTerms> CircleSystem::energy(const State& state) const {
  const double half_r2 = 0.5 * state.y.squaredNorm();
  return EnergyTerms{.kinetic = half_r2, .gravity = 0.0, .spring = half_r2};
}

Eigen::Matrix<double, Eigen::Dynamic, 6> CircleSystem::particleRows(const State& state) {
  Eigen::Matrix<double, Eigen::Dynamic, 6> rows(1, 6);
  rows << state.y[0], state.y[1], 0.0, -state.y[1], state.y[0], 0.0;
  return rows;
}

State CircleSystem::initialState() const { return State{0.0, start_}; }

Model circleTwin(const Model& circle) {
  Model twin;
  const Eigen::Vector2d p = *circle.circle_start;
  twin.mass = Vector::Ones(2);
  twin.pinned = {1, 0};
  twin.start_position = Vector::Zero(6);
  twin.start_velocity = Vector::Zero(6);
  at3(twin.start_position, kCircleTwinParticle) = Vec3(p.x(), p.y(), 0.0);
  at3(twin.start_velocity, kCircleTwinParticle) = Vec3(-p.y(), p.x(), 0.0);
  twin.springs.push_back(Spring{0, kCircleTwinParticle, 0.0, 1.0, 0.0, SpringFamily::Custom});
  return twin;
}

}  // namespace mysim
