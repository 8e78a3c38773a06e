#include "integrators/implicit_euler_step.h"

#include <algorithm>
#include <limits>
#include <cmath>

namespace mysim {

void prepareImplicitEulerStep(const ParticleSystem& ps, const State& s, double h,
                              ImplicitEulerStep& step) {
  const Model& model = ps.model();
  const int n = ps.particleCount();
  step.h = h;
  step.t_end = s.t + h;
  step.x0 = s.y.head(3 * n);
  step.target.resize(3 * n);
  step.mass_over_h2.resize(n);
  step.holds.clear(n);
  const Vector zero_velocity = Vector::Zero(3 * n);  // external force without its drag term
  double load_squared = 0.0;
  for (int p = 0; p < n; ++p) {
    const double m = model.mass[p], m_eff = m + h * model.drag;
    step.mass_over_h2[p] = m_eff / (h * h);
    if (model.pinned[p]) {
      step.target.segment<3>(3 * p) = ps.pinPosition(p, step.t_end);
      continue;
    }
    const Vec3 x0 = s.y.segment<3>(3 * p), v0 = s.y.segment<3>(3 * n + 3 * p);
    const Vec3 f_end = ps.externalForce(p, step.t_end, zero_velocity.data());
    load_squared += f_end.squaredNorm();
    step.target.segment<3>(3 * p) = (m * (x0 + h * v0) + h * model.drag * x0 + h * h * f_end) / m_eff;
  }
  step.load = std::sqrt(load_squared);
}

void implicitEulerResidual(const ParticleSystem& ps, const ImplicitEulerStep& step,
                           const Vector& x, Vector& r) {
  implicitEulerForces(ps, step, x, r);
  step.holds.removeReactions(r);
}

bool holdContacts(const ParticleSystem& ps, ImplicitEulerStep& step, Vector& x, Vector& scratch) {
  bool measured = false;
  const HoldReaction reaction = [&](int p) -> Vec3 {
    if (!measured) implicitEulerForces(ps, step, x, scratch), measured = true;
    return scratch.segment<3>(3 * p);  // m~/h^2 (x - y~) = f + R: R = r
  };
  return step.holds.hold(ps, step.x0, step.h, x, reaction) > 0;
}

void implicitEulerForces(const ParticleSystem& ps, const ImplicitEulerStep& step,
                         const Vector& x, Vector& r) {
  const Model& model = ps.model();
  const int n = ps.particleCount();
  r.resize(3 * n);
  for (int p = 0; p < n; ++p) {
    r.segment<3>(3 * p) =
        step.mass_over_h2[p] * (x.segment<3>(3 * p) - step.target.segment<3>(3 * p));
  }
  for (const Spring& sp : model.springs) {
    const Vec3 d = x.segment<3>(3 * sp.i) - x.segment<3>(3 * sp.j);
    const double l = d.norm();
    const Vec3 u = d / l;
    const Vec3 moved = d - (step.x0.segment<3>(3 * sp.i) - step.x0.segment<3>(3 * sp.j));
    const Vec3 g = sp.stiffness * (l - sp.rest_length) * u + (sp.damping / step.h) * u.dot(moved) * u;
    r.segment<3>(3 * sp.i) += g;
    r.segment<3>(3 * sp.j) -= g;
  }
  for (const Hinge& hinge : model.hinges) {  // grad of 1/2 k |b|^2: k w_a b
    const Vec3 kb = hinge.stiffness * hingeVector(hinge, x.data());
    for (int a = 0; a < 4; ++a) r.segment<3>(3 * hinge.particle[a]) += hinge.weight[a] * kb;
  }
  for (const ContactHold& hold : step.holds.all()) r.segment<3>(3 * hold.particle) -= hold.force;
  for (int p = 0; p < n; ++p) {
    if (model.pinned[p]) r.segment<3>(3 * p).setZero();
  }
}

double stepLoad(const ParticleSystem& ps, double t) {
  const Model& model = ps.model();
  const int n = ps.particleCount();
  const Vector zero_velocity = Vector::Zero(3 * n);
  double sum = 0.0;
  for (int p = 0; p < n; ++p) {
    if (!model.pinned[p]) sum += ps.externalForce(p, t, zero_velocity.data()).squaredNorm();
  }
  return std::sqrt(sum);
}

PassResidual implicitEulerPassResidual(const ParticleSystem& ps, const ImplicitEulerStep& step,
                                       const Vector& x, Vector& r) {
  implicitEulerResidual(ps, step, x, r);  // inertia + springs + hinges
  const Model& model = ps.model();
  double inertia = 0.0, springs = 0.0, scale = 0.0;
  for (int p = 0; p < ps.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    const Vec3 a = step.mass_over_h2[p] * (x.segment<3>(3 * p) - step.target.segment<3>(3 * p));
    inertia += a.squaredNorm();
    springs += (r.segment<3>(3 * p) - a).squaredNorm();
    scale += (step.mass_over_h2[p] * x.segment<3>(3 * p)).squaredNorm();
  }
  constexpr double kRoundOffUlps = 64.0;
  return {r.norm(), std::max({step.load, std::sqrt(inertia), std::sqrt(springs)}),
          kRoundOffUlps * std::numeric_limits<double>::epsilon() * std::sqrt(scale)};
}

void finishImplicitEulerStep(OdeSystem& system, const ImplicitEulerStep& step, const Vector& x,
                             State& s) {
  const Eigen::Index n3 = step.x0.size();
  s.y.tail(n3) = (x - step.x0) / step.h;
  s.y.head(n3) = x;
  s.t = step.t_end;
  system.afterStep(s);
}

}  // namespace mysim
