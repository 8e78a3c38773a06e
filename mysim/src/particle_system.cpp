#include "mysim/particle_system.h"

#include <cmath>
#include <string>

namespace mysim {

ParticleSystem::ParticleSystem(Model model, BlowUpLimits limits)
    : model_(std::move(model)), limits_(limits) {
  // The energy scale a healthy run stays within: what it starts with, plus all that gravity can
  // release over the scene's extent, plus work wind and driven pins can do at that scale.
  const Vector& x = model_.start_position;
  const int n = particleCount();
  Vec3 low = at3(x, 0), high = at3(x, 0);
  double free_mass = 0.0;
  for (int p = 0; p < n; ++p) {
    low = low.cwiseMin(at3(x, p));
    high = high.cwiseMax(at3(x, p));
    if (!model_.pinned[p]) free_mass += model_.mass[p];
  }
  double rest_total = 0.0;
  for (const Spring& s : model_.springs) rest_total += s.rest_length;
  const double extent = (high - low).norm() + rest_total / std::max(1, n) + 1e-3;
  const EnergyTerms e0 = mechanicalEnergy(model_, x, model_.start_velocity);
  energy_scale_ = e0.kinetic + e0.spring + free_mass * model_.gravity.norm() * extent;
  if (model_.wind) energy_scale_ += model_.wind->strength * (1 + model_.wind->gust) * n * extent;
  if (model_.pin_motion) {
    const double speed = model_.pin_motion->velocity(0.0).norm();
    energy_scale_ += free_mass * speed * speed;
  }
  energy_scale_ = std::max(energy_scale_, 1e-9);
}

State ParticleSystem::initialState() const {
  const int n = particleCount();
  State s;
  s.y.resize(6 * n);
  s.y.head(3 * n) = model_.start_position;
  s.y.tail(3 * n) = model_.start_velocity;
  afterStepConst(s);
  return s;
}

Vec3 ParticleSystem::pinPosition(int particle, double t) const {
  const Vec3 start = at3(model_.start_position, particle);
  return model_.pin_motion ? Vec3(start + model_.pin_motion->offset(t)) : start;
}

Vec3 ParticleSystem::pinVelocity(double t) const {
  return model_.pin_motion ? model_.pin_motion->velocity(t) : Vec3::Zero();
}

void ParticleSystem::force(double t, const Vector& x, const Vector& v, Vector& f) const {
  const int n = particleCount();
  f.resize(3 * n);
  for (int p = 0; p < n; ++p) at3(f, p) = model_.mass[p] * model_.gravity;
  if (model_.drag != 0.0) f -= model_.drag * v;
  if (model_.wind) {
    for (int p = 0; p < n; ++p) at3(f, p) += windForce(*model_.wind, p, t);
  }
  for (const Spring& s : model_.springs) {
    const Vec3 fi = springForce(at3(x, s.i), at3(x, s.j), at3(v, s.i), at3(v, s.j), s.rest_length,
                                s.stiffness, s.damping);
    at3(f, s.i) += fi;
    at3(f, s.j) -= fi;
  }
}

void ParticleSystem::acceleration(double t, const Vector& x, const Vector& v, Vector& a) const {
  force(t, x, v, a);
  const Vec3 pin_acceleration =
      model_.pin_motion ? model_.pin_motion->acceleration(t) : Vec3::Zero();
  for (int p = 0; p < particleCount(); ++p) {
    if (model_.pinned[p]) {
      at3(a, p) = pin_acceleration;
    } else {
      at3(a, p) /= model_.mass[p];
    }
  }
}

void ParticleSystem::derivative(double t, const Vector& y, Vector& dydt) {
  const int n3 = 3 * particleCount();
  dydt.resize(2 * n3);
  // Segments of y are copied into the scratch vectors: the force code indexes plain 3N arrays.
  x_scratch_ = y.head(n3);
  v_scratch_ = y.tail(n3);
  acceleration(t, x_scratch_, v_scratch_, a_scratch_);
  dydt.head(n3) = v_scratch_;
  const Vec3 pin_velocity = pinVelocity(t);
  for (int p = 0; p < particleCount(); ++p) {
    if (model_.pinned[p]) at3(dydt, p) = pin_velocity;
  }
  dydt.tail(n3) = a_scratch_;
}

void ParticleSystem::afterStepConst(State& state) const {
  const int n3 = 3 * particleCount();
  const Vec3 pin_velocity = pinVelocity(state.t);
  for (int p = 0; p < particleCount(); ++p) {
    if (!model_.pinned[p]) continue;
    state.y.segment<3>(3 * p) = pinPosition(p, state.t);
    state.y.segment<3>(n3 + 3 * p) = pin_velocity;
  }
  if (model_.sphere) {
    resolveSphereContacts(*model_.sphere, model_.pinned, state.y.head(n3), state.y.tail(n3));
  }
}

void ParticleSystem::afterStep(State& state) { afterStepConst(state); }

double ParticleSystem::maxStrain(const Vector& x) const {
  double worst = 0.0;
  for (const Spring& s : model_.springs) {
    const double l = (at3(x, s.j) - at3(x, s.i)).norm();
    worst = std::max(worst, std::abs(l / s.rest_length - 1.0));
  }
  return worst;
}

std::optional<OdeSystem::Unhealthy> ParticleSystem::checkHealth(const State& state) const {
  if (!state.y.allFinite()) return Unhealthy{"non-finite", "a position or velocity is NaN or inf"};
  const int n3 = 3 * particleCount();
  const Vector x = state.y.head(n3);
  const double strain = maxStrain(x);
  if (strain > limits_.max_strain) {
    return Unhealthy{"strain", "max spring strain " + std::to_string(strain) + " > " +
                                   std::to_string(limits_.max_strain)};
  }
  const EnergyTerms e = mechanicalEnergy(model_, x, state.y.tail(n3));
  const double limit = limits_.max_energy_ratio * energy_scale_;
  if (e.kinetic > limit) {
    return Unhealthy{"energy", "kinetic energy " + std::to_string(e.kinetic) + " J > " +
                                   std::to_string(limit) + " J"};
  }
  return std::nullopt;
}

std::optional<EnergyTerms> ParticleSystem::energy(const State& state) const {
  const int n3 = 3 * particleCount();
  return mechanicalEnergy(model_, state.y.head(n3), state.y.tail(n3));
}

Eigen::Matrix<double, Eigen::Dynamic, 6> ParticleSystem::particleRows(const State& state) {
  const int n = particleCount();
  Eigen::Matrix<double, Eigen::Dynamic, 6> rows(n, 6);
  for (int p = 0; p < n; ++p) {
    rows.block<1, 3>(p, 0) = state.y.segment<3>(3 * p).transpose();
    rows.block<1, 3>(p, 3) = state.y.segment<3>(3 * n + 3 * p).transpose();
  }
  return rows;
}

}  // namespace mysim
