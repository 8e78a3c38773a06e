#include "compare/metrics/momentum_metric.h"

#include <algorithm>

namespace springcheck {

bool conservesMomentum(const mysim::Model& model) {
  const bool pinned =
      std::any_of(model.pinned.begin(), model.pinned.end(), [](char p) { return p != 0; });
  return !pinned && model.drag == 0.0 && !model.wind && model.colliders.empty() && !model.isCircle();
}

std::optional<MomentumDrift> momentumDrift(const mysim::Model& model, const mysim::RunRecord& run) {
  if (!conservesMomentum(model) || run.frames.empty()) return std::nullopt;
  const double total_mass = model.mass.sum();
  struct Moments {
    mysim::Vec3 linear, angular;
    double linear_scale, angular_scale;
  };
  auto moments = [&](const mysim::ParticleRows& f) {
    mysim::Vec3 centre = mysim::Vec3::Zero(), centre_velocity = mysim::Vec3::Zero();
    for (int i = 0; i < f.rows(); ++i) {
      centre += model.mass[i] * f.row(i).head<3>().transpose();
      centre_velocity += model.mass[i] * f.row(i).tail<3>().transpose();
    }
    centre /= total_mass;
    centre_velocity /= total_mass;
    Moments m{mysim::Vec3::Zero(), mysim::Vec3::Zero(), 0.0, 0.0};
    for (int i = 0; i < f.rows(); ++i) {
      const mysim::Vec3 r = f.row(i).head<3>().transpose() - centre;
      const mysim::Vec3 v = f.row(i).tail<3>().transpose();
      m.linear += model.mass[i] * v;
      m.angular += model.mass[i] * r.cross(v - centre_velocity);
      m.linear_scale += model.mass[i] * v.norm();
      m.angular_scale += model.mass[i] * r.norm() * (v - centre_velocity).norm();
    }
    return m;
  };
  const Moments start = moments(run.frames.front());
  double linear = 0.0, angular = 0.0, linear_scale = 0.0, angular_scale = 0.0;
  for (std::size_t k = 0; k < run.frames.size(); ++k) {
    const Moments m = moments(run.frames[k]);
    const double t = run.times[k] - run.times.front();
    linear = std::max(linear, (m.linear - start.linear - total_mass * model.gravity * t).norm());
    angular = std::max(angular, (m.angular - start.angular).norm());
    linear_scale = std::max(linear_scale, m.linear_scale);
    angular_scale = std::max(angular_scale, m.angular_scale);
  }
  if (linear_scale == 0.0) return std::nullopt;  // nothing moved
  return MomentumDrift{linear / linear_scale, angular_scale > 0.0 ? angular / angular_scale : 0.0};
}

}  // namespace springcheck
