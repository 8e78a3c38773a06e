#include "compare/closed_form.h"

#include <cmath>
#include <numbers>

namespace springcheck {

double ellipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  while (std::abs(a - b) > 1e-15 * a) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return std::numbers::pi / (2.0 * a);
}

namespace {

std::optional<ClosedFormError> circleError(const mysim::Scene& scene, const mysim::RunRecord& run) {
  double worst = 0.0;
  const Eigen::Vector2d s = scene.circle_start;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const double t = run.times[f];
    const Eigen::Vector2d exact(s.x() * std::cos(t) - s.y() * std::sin(t),
                                s.x() * std::sin(t) + s.y() * std::cos(t));
    worst = std::max(worst, (run.frames[f].row(0).head<2>().transpose() - exact).norm());
  }
  return ClosedFormError{"circle position", worst, s.norm()};
}

std::optional<ClosedFormError> chainSagError(const mysim::Scene& scene,
                                             const mysim::RunRecord& run) {
  const mysim::ChainShape& c = scene.chain;
  const int n = c.particles - 1;
  const double g = scene.gravity.norm();
  const mysim::Vec3 down = scene.gravity / g;
  double worst = 0.0, end = 0.0;
  for (int j = 1; j <= n; ++j) {
    const double drop =
        j * c.rest_length + (c.particle_mass * g / c.stiffness) * j * (2 * n - j + 1) / 2.0;
    const mysim::Vec3 exact = c.origin + drop * down;
    worst = std::max(worst, (run.frames.back().row(j).head<3>().transpose() - exact).norm());
    end = drop;
  }
  return ClosedFormError{"hanging chain at rest", worst, end};
}

std::optional<ClosedFormError> pendulumPeriodError(const mysim::Scene& scene,
                                                   const mysim::RunRecord& run) {
  const mysim::ChainShape& c = scene.chain;
  const double g = scene.gravity.norm();
  const mysim::Vec3 down = scene.gravity / g;
  // Released at rest at angle theta0 from the downward vertical.
  const double theta0 = std::acos(std::clamp(c.direction.normalized().dot(down), -1.0, 1.0));
  const double period = 4.0 * std::sqrt(c.rest_length / g) * ellipticK(std::sin(theta0 / 2));
  // Horizontal offset of the bob from the pin, along the start direction's horizontal part.
  const mysim::Vec3 across = (c.direction - c.direction.dot(down) * down).normalized();
  std::vector<double> crossings;  // times the bob crosses below the pin going the same way
  double previous = 0.0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const double u = across.dot(run.frames[f].row(1).head<3>().transpose() - c.origin);
    if (f > 0 && previous > 0 && u <= 0) {
      crossings.push_back(run.times[f - 1] +
                          (run.times[f] - run.times[f - 1]) * previous / (previous - u));
    }
    previous = u;
  }
  if (crossings.size() < 2) return std::nullopt;
  const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  return ClosedFormError{"pendulum period", std::abs(measured / period - 1.0), period};
}

}  // namespace

std::optional<ClosedFormError> closedFormError(const mysim::Scene& scene,
                                               const mysim::RunRecord& run) {
  if (run.frames.empty()) return std::nullopt;
  if (scene.kind == mysim::SystemKind::Circle) return circleError(scene, run);
  if (scene.kind != mysim::SystemKind::Chain || scene.pins != std::vector<int>{0} ||
      scene.gravity.norm() == 0.0 || scene.wind || scene.pin_motion || scene.sphere) {
    return std::nullopt;
  }
  const double alignment = scene.chain.direction.normalized().dot(scene.gravity.normalized());
  if (alignment > 1.0 - 1e-12) return chainSagError(scene, run);
  if (scene.chain.particles == 2 && scene.drag == 0.0 && scene.chain.damping == 0.0) {
    return pendulumPeriodError(scene, run);
  }
  return std::nullopt;
}

}  // namespace springcheck
