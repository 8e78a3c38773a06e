#include "mysim/particle_system.h"
#include "mysim/contact.h"
#include "mysim/energy.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "forces/spring_forces.h"
#include "solvers/vector_ops.h"
#include "core/parallel_threshold.h"

namespace mysim {


ParticleSystem::ParticleSystem(std::shared_ptr<const Model> model, BlowUpLimits limits)
    : shared_model_(std::move(model)),
      model_(*shared_model_),
      limits_(limits),
      adjacency_(SpringAdjacency::build(model_.particleCount(), model_.springs)),
      spring_scale_(static_cast<Eigen::Index>(model_.springs.size())),
      hinge_adjacency_(HingeAdjacency::build(model_.particleCount(), model_.hinges)),
      hinge_force_(3 * static_cast<Eigen::Index>(model_.hinges.size())) {
  if (model_.self_collision_thickness) self_collision_.emplace(model_);
  for (const Spring& s : model_.springs) damped_springs_ |= s.damping != 0.0;
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
  return pinnedPosition(model_, particle, t);
}

Vec3 ParticleSystem::pinVelocity(double t) const { return pinnedVelocity(model_, t); }

void ParticleSystem::force(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                           Eigen::Ref<Vector> f) const {
  gather(t, x, v, f, false);
}

void ParticleSystem::referenceForce(double t, Eigen::Ref<const Vector> x,
                                    Eigen::Ref<const Vector> v, Eigen::Ref<Vector> f) const {
  gatherPerEnd(t, x, v, f);
}

void ParticleSystem::acceleration(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                                  Eigen::Ref<Vector> a) const {
  gather(t, x, v, a, true);
}

Vec3 ParticleSystem::externalForce(int p, double t, const double* v) const {
  Vec3 f = model_.mass[p] * model_.gravity - model_.drag * Eigen::Map<const Vec3>(v + 3 * p);
  if (model_.wind) f += windForce(*model_.wind, p, t);
  return f;
}

Vec3 ParticleSystem::particleForce(int p, double t, const double* xs, const double* vs) const {
  const SpringAdjacency& a = adjacency_;
  const HingeAdjacency& ha = hinge_adjacency_;
  const double* scale = spring_scale_.data();
  const double* hinge_force = hinge_force_.data();
  const double* xp = xs + 3 * p;
  const Vec3 fp = externalForce(p, t, vs);
  double sx = fp.x(), sy = fp.y(), sz = fp.z();
  for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
    const double* xq = xs + 3 * a.other[e];
    const double k = scale[a.spring[e]];
    sx += k * (xq[0] - xp[0]);
    sy += k * (xq[1] - xp[1]);
    sz += k * (xq[2] - xp[2]);
  }
  // Then the hinges around p: -w k b each, in the hinge adjacency's order.
  for (int e = ha.offsets[p]; e < ha.offsets[p + 1]; ++e) {
    const double w = model_.hinges[ha.hinge[e]].weight[ha.slot[e]];
    const double* kb = hinge_force + 3 * ha.hinge[e];
    sx -= w * kb[0];
    sy -= w * kb[1];
    sz -= w * kb[2];
  }
  return Vec3(sx, sy, sz);
}

void ParticleSystem::gather(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                            Eigen::Ref<Vector> f, bool accelerations) const {
  const int n = particleCount();
  const int springs = static_cast<int>(model_.springs.size());
  const Vec3 pin_acceleration =
      model_.pin_motion ? model_.pin_motion->acceleration(t) : Vec3::Zero();
  const double* xs = x.data();
  const double* vs = v.data();
  double* fs = f.data();
  double* scale = spring_scale_.data();
  // Blocks of springs a thread takes at a time: long enough for the vector loop, short enough
  // to share out evenly.
  constexpr int kBlock = 512;
  const int blocks = (springs + kBlock - 1) / kBlock;
  const int hinges = static_cast<int>(model_.hinges.size());
  double* hinge_force = hinge_force_.data();
#pragma omp parallel if (n >= kParallelParticles)
  {
    // 1b. Every hinge's k b, once (hinge.h).
#pragma omp for schedule(static)
    for (int k = 0; k < hinges; ++k) {
      const Hinge& h = model_.hinges[k];
      Eigen::Map<Vec3>(hinge_force + 3 * k) = h.stiffness * hingeVector(h, xs);
    }
    // 1. Every spring's force scale, once.
#pragma omp for schedule(static)
    for (int b = 0; b < blocks; ++b) {
      springScales(model_.springs, damped_springs_, xs, vs, scale, b * kBlock,
                   std::min(springs, (b + 1) * kBlock));
    }
    // 2. Each particle's sum, in the adjacency's fixed order: scale (x_q - x_p) per spring, the
    // per-end loop's own arithmetic.
#pragma omp for schedule(static)
    for (int p = 0; p < n; ++p) {
      Vec3 sum = particleForce(p, t, xs, vs);
      if (accelerations) {
        if (model_.pinned[p]) {
          Eigen::Map<Vec3>(fs + 3 * p) = pin_acceleration;
          continue;
        }
        sum *= 1.0 / model_.mass[p];
      }
      Eigen::Map<Vec3>(fs + 3 * p) = sum;
    }
  }
}

void ParticleSystem::gatherPerEnd(double t, Eigen::Ref<const Vector> x, Eigen::Ref<const Vector> v,
                                  Eigen::Ref<Vector> f) const {
  const int n = particleCount();
  const double* xs = x.data();
  const double* vs = v.data();
  double* fs = f.data();
  const SpringAdjacency& a = adjacency_;
#pragma omp parallel for schedule(static) if (n >= kParallelParticles)
  for (int p = 0; p < n; ++p) {
    const Eigen::Map<const Vec3> xp(xs + 3 * p), vp(vs + 3 * p);
    const Vec3 fp = externalForce(p, t, vs);
    // springForce() written out on scalars, from each end: one square root and one division
    // per incidence.
    double fx = fp.x(), fy = fp.y(), fz = fp.z();
    for (int e = a.offsets[p]; e < a.offsets[p + 1]; ++e) {
      const double* xq = xs + 3 * a.other[e];
      const Spring& s = model_.springs[a.spring[e]];
      const double dx = xq[0] - xp.x(), dy = xq[1] - xp.y(), dz = xq[2] - xp.z();
      const double inv_l = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz);
      // F = [k (l - rest) + c u.w] u = [k (1 - rest / l) + c (d.w) / l^2] d
      double scale = s.stiffness * (1.0 - s.rest_length * inv_l);
      if (s.damping != 0.0) {
        const double* vq = vs + 3 * a.other[e];
        const double dw = dx * (vq[0] - vp.x()) + dy * (vq[1] - vp.y()) + dz * (vq[2] - vp.z());
        scale += s.damping * dw * inv_l * inv_l;
      }
      fx += scale * dx;
      fy += scale * dy;
      fz += scale * dz;
    }
    for (int e = hinge_adjacency_.offsets[p]; e < hinge_adjacency_.offsets[p + 1]; ++e) {
      const Hinge& h = model_.hinges[hinge_adjacency_.hinge[e]];
      const double w = h.weight[hinge_adjacency_.slot[e]];
      const Vec3 kb = h.stiffness * hingeVector(h, xs);  // the fast path's operations
      fx -= w * kb.x();
      fy -= w * kb.y();
      fz -= w * kb.z();
    }
    fs[3 * p] = fx;
    fs[3 * p + 1] = fy;
    fs[3 * p + 2] = fz;
  }
}

void ParticleSystem::derivative(double t, const Vector& y, Vector& dydt) {
  const int n3 = 3 * particleCount();
  dydt.resize(2 * n3);
  acceleration(t, y.head(n3), y.tail(n3), dydt.tail(n3));
  copyParallel(y.tail(n3), dydt.head(n3));
  if (model_.pin_motion) {
    const Vec3 pin_velocity = pinVelocity(t);
    for (int p = 0; p < particleCount(); ++p) {
      if (model_.pinned[p]) dydt.segment<3>(3 * p) = pin_velocity;
    }
  } else {
    for (int p = 0; p < particleCount(); ++p) {
      if (model_.pinned[p]) dydt.segment<3>(3 * p).setZero();
    }
  }
}

void ParticleSystem::afterStepConst(State& state) const {
  const int n3 = 3 * particleCount();
  const Vec3 pin_velocity = pinVelocity(state.t);
  for (int p = 0; p < particleCount(); ++p) {
    if (!model_.pinned[p]) continue;
    state.y.segment<3>(3 * p) = pinPosition(p, state.t);
    state.y.segment<3>(n3 + 3 * p) = pin_velocity;
  }
  if (model_.colliders.empty() && !self_collision_) return;
  // Friction and self-collision need where each particle was when this step began: the state
  // the previous call left, when this state follows it in time (else, as at the start, the
  // state itself). Self-contacts first, the colliders last: nothing ends inside a collider.
  if (step_start_.size() != n3 || !(state.t > step_start_t_)) step_start_ = state.y.head(n3);
  selfContactPass(step_start_, state.y.head(n3), state.y.tail(n3));
  if (!model_.colliders.empty()) {
    resolveContacts(model_.colliders, model_.pinned, step_start_, state.y.head(n3), state.y.tail(n3));
  }
  step_start_ = state.y.head(n3);
  step_start_t_ = state.t;
}

void ParticleSystem::selfContactPass(Eigen::Ref<const Vector> start, Eigen::Ref<Vector> x,
                                     Eigen::Ref<Vector> v) const {
  if (self_collision_) self_collision_->resolve(start, x, v);
}

void ParticleSystem::afterStep(State& state) { afterStepConst(state); }

double ParticleSystem::maxStrain(Eigen::Ref<const Vector> x) const {
  return maxSpringStrain(model_.springs, x);
}

std::optional<OdeSystem::Unhealthy> ParticleSystem::checkHealth(const State& state) const {
  if (!state.y.allFinite()) return Unhealthy{"non-finite", "a position or velocity is NaN or inf"};
  const int n3 = 3 * particleCount();
  const double strain = maxStrain(state.y.head(n3));
  if (strain > limits_.max_strain) {
    return Unhealthy{"strain", "max spring strain " + std::to_string(strain) + " > " +
                                   std::to_string(limits_.max_strain)};
  }
  // Only the kinetic energy is bounded: a pass over particles, not the springs again. What
  // gravity has released so far (m g . (x - x0), summed) is energy a healthy run may hold on top
  // of the scale: a long fall or slide is not a runaway (a particle sliding 0.3 m down an
  // incline exceeded a bound of the start's scale alone).
  double kinetic = 0.0, released = 0.0;
  for (int p = 0; p < particleCount(); ++p) {
    if (model_.pinned[p]) continue;
    kinetic += 0.5 * model_.mass[p] * state.y.segment<3>(n3 + 3 * p).squaredNorm();
    released += model_.mass[p] *
                model_.gravity.dot(state.y.segment<3>(3 * p) - at3(model_.start_position, p));
  }
  const double limit = limits_.max_energy_ratio * (energy_scale_ + std::max(released, 0.0));
  if (kinetic > limit) {
    return Unhealthy{"energy", "kinetic energy " + std::to_string(kinetic) + " J > " +
                                   std::to_string(limit) + " J (" +
                                   std::to_string(limits_.max_energy_ratio) +
                                   " times the energy scale and what gravity has released)"};
  }
  return std::nullopt;
}

double ParticleSystem::pinPower(const State& state) const {
  const int n = particleCount();
  const auto x = state.y.head(3 * n);
  const auto v = state.y.tail(3 * n);
  double power = 0.0;
  for (int p = 0; p < n; ++p) {
    if (!model_.pinned[p]) continue;
    Vec3 on_pin = Vec3::Zero();
    for (int e = adjacency_.offsets[p]; e < adjacency_.offsets[p + 1]; ++e) {
      const int q = adjacency_.other[e];
      const Spring& sp = model_.springs[adjacency_.spring[e]];
      on_pin += springForce(x.segment<3>(3 * p), x.segment<3>(3 * q), v.segment<3>(3 * p),
                            v.segment<3>(3 * q), sp.rest_length, sp.stiffness, sp.damping);
    }
    power -= on_pin.dot(v.segment<3>(3 * p));
  }
  return power;
}

double ParticleSystem::externalWork(const State& before, const State& after) const {
  double work = 0.0;
  if (model_.wind) {
    const double t_mid = 0.5 * (before.t + after.t);
    for (int p = 0; p < particleCount(); ++p) {
      if (model_.pinned[p]) continue;
      work += windForce(*model_.wind, p, t_mid)
                  .dot(after.y.segment<3>(3 * p) - before.y.segment<3>(3 * p));
    }
  }
  if (model_.pin_motion) work += 0.5 * (pinPower(before) + pinPower(after)) * (after.t - before.t);
  return work;
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
