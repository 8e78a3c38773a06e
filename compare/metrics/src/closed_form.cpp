#include "compare/metrics/closed_form.h"

#include <cmath>
#include <numbers>

#include "compare/metrics/cantilever_metric.h"

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

std::optional<ClosedFormError> circleError(const mysim::Model& model, const mysim::RunRecord& run) {
  double worst = 0.0;
  const Eigen::Vector2d s = model.circle_start;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const double t = run.times[f];
    const Eigen::Vector2d exact(s.x() * std::cos(t) - s.y() * std::sin(t),
                                s.x() * std::sin(t) + s.y() * std::cos(t));
    worst = std::max(worst, (run.frames[f].row(0).head<2>().transpose() - exact).norm());
  }
  return ClosedFormError{"circle position", worst, s.norm()};
}

// A uniform chain read back from its model: what the closed forms need.
struct UniformChain {
  int particles;
  double rest_length, particle_mass, stiffness, damping;
  mysim::Vec3 origin, direction;
};

// The chain's parameters, if the model is a chain of equal springs and equal free masses.
std::optional<UniformChain> uniformChain(const mysim::Model& model) {
  if (model.kind != mysim::SystemKind::Chain || model.springs.empty()) return std::nullopt;
  const mysim::Spring& s0 = model.springs.front();
  for (const mysim::Spring& s : model.springs) {
    if (s.rest_length != s0.rest_length || s.stiffness != s0.stiffness || s.damping != s0.damping) {
      return std::nullopt;
    }
  }
  for (int p = 1; p < model.particleCount(); ++p) {
    if (model.mass[p] != model.mass[1]) return std::nullopt;
  }
  const mysim::Vec3 origin = mysim::at3(model.start_position, 0);
  const mysim::Vec3 next = mysim::at3(model.start_position, 1);
  return UniformChain{
      model.particleCount(),       s0.rest_length, model.mass[1], s0.stiffness, s0.damping, origin,
      (next - origin).normalized()};
}

// How far the nodes moved from the frame nearest to 90 % of the run to the last: the motion still
// going on, which an at-rest closed form cannot tell from error.
double motionLeft(const mysim::RunRecord& run) {
  const double t_end = run.times.back();
  std::size_t earlier = 0;
  for (std::size_t f = 0; f < run.times.size(); ++f) {
    if (std::abs(run.times[f] - 0.9 * t_end) < std::abs(run.times[earlier] - 0.9 * t_end)) earlier = f;
  }
  double moved = 0.0;
  for (int j = 0; j < run.frames.back().rows(); ++j) {
    moved = std::max(moved, (run.frames.back().row(j).head<3>() - run.frames[earlier].row(j).head<3>()).norm());
  }
  return moved;
}

std::optional<ClosedFormError> chainSagError(const mysim::Model& model, const UniformChain& c,
                                             const mysim::RunRecord& run) {
  const int n = c.particles - 1;
  const double g = model.gravity.norm();
  const mysim::Vec3 down = model.gravity / g;
  double worst = 0.0, end = 0.0;
  for (int j = 1; j <= n; ++j) {
    const double drop =
        j * c.rest_length + (c.particle_mass * g / c.stiffness) * j * (2 * n - j + 1) / 2.0;
    const mysim::Vec3 exact = c.origin + drop * down;
    worst = std::max(worst, (run.frames.back().row(j).head<3>().transpose() - exact).norm());
    end = drop;
  }
  ClosedFormError e{"hanging chain at rest", worst, end};
  e.motion_left = motionLeft(run);
  return e;
}

std::optional<ClosedFormError> pendulumPeriodError(const mysim::Model& model, const UniformChain& c,
                                                   const mysim::RunRecord& run) {
  const double g = model.gravity.norm();
  const mysim::Vec3 down = model.gravity / g;
  // Released at rest at angle theta0 from the downward vertical.
  const double theta0 = std::acos(std::clamp(c.direction.dot(down), -1.0, 1.0));
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

// The elastic chain hanging between two pins, at rest: segments s = 0..S-1 of rest length L and
// stiffness k between equal masses m. Each free node's balance makes the tension vectors
// T_s = (H, V + s m g) in the plane of the span (e1 across, e2 up): the horizontal part is one H,
// the vertical part grows by m g a node. Segment s is T_s / |T_s| long L + |T_s| / k, and the
// segments must add up to the span D between the pins:
//   F(H, V) = sum_s (L / |T_s| + 1 / k) T_s - D = 0,
// solved by Newton with its exact Jacobian sum_s [(L/|T| + 1/k) I - L T T^T / |T|^3] to 1e-13 of
// |D| (the discrete closed form: any N, any slack or stretch, no small-sag approximation).
std::optional<std::vector<mysim::Vec3>> twoPinCatenary(const mysim::Model& model, const UniformChain& c) {
  const int segments = c.particles - 1;
  const double g = model.gravity.norm(), m = c.particle_mass, L = c.rest_length, k = c.stiffness;
  const mysim::Vec3 up = -model.gravity / g;
  const mysim::Vec3 left = mysim::at3(model.start_position, 0);
  const mysim::Vec3 span = mysim::at3(model.start_position, segments) - left;
  const mysim::Vec3 across3 = span - span.dot(up) * up;
  if (across3.norm() < 1e-9 * std::max(1.0, span.norm())) return std::nullopt;  // one above the other
  const mysim::Vec3 e1 = across3.normalized();
  const Eigen::Vector2d D(span.dot(e1), span.dot(up));
  // Start: a taut line's tension across, the weight shared by the two pins.
  Eigen::Vector2d x(k * std::max(1e-3 * L, D.x() / segments), -0.5 * (segments - 1) * m * g);
  for (int iteration = 0; iteration < 200; ++iteration) {
    Eigen::Vector2d F = -D;
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
    for (int s = 0; s < segments; ++s) {
      const Eigen::Vector2d T(x.x(), x.y() + s * m * g);
      const double t = T.norm();
      F += (L / t + 1.0 / k) * T;
      J += (L / t + 1.0 / k) * Eigen::Matrix2d::Identity() - (L / (t * t * t)) * T * T.transpose();
    }
    if (F.norm() < 1e-13 * D.norm()) {
      std::vector<mysim::Vec3> nodes{left};
      for (int s = 0; s < segments; ++s) {
        const Eigen::Vector2d T(x.x(), x.y() + s * m * g);
        const Eigen::Vector2d step = (L / T.norm() + 1.0 / k) * T;
        nodes.push_back(nodes.back() + step.x() * e1 + step.y() * up);
      }
      return nodes;
    }
    Eigen::Vector2d dx = J.lu().solve(-F);
    // Keep the tension across positive (a chain pulls, never pushes).
    while (x.x() + dx.x() <= 0.0) dx *= 0.5;
    x += dx;
  }
  return std::nullopt;
}

std::optional<ClosedFormError> twoPinCatenaryError(const mysim::Model& model, const UniformChain& c,
                                                   const mysim::RunRecord& run) {
  const auto nodes = twoPinCatenary(model, c);
  if (!nodes) return std::nullopt;
  const mysim::Vec3 up = -model.gravity.normalized();
  double worst = 0.0, deepest = 0.0;
  for (int j = 1; j + 1 < c.particles; ++j) {
    worst = std::max(worst, (run.frames.back().row(j).head<3>().transpose() - (*nodes)[j]).norm());
    deepest = std::max(deepest, ((*nodes)[0] - (*nodes)[j]).dot(up));
  }
  ClosedFormError e{"two-pin catenary at rest", worst, deepest};
  e.motion_left = motionLeft(run);
  return e;
}

}  // namespace

std::optional<std::vector<mysim::Vec3>> twoPinCatenaryNodes(const mysim::Model& model) {
  const std::optional<UniformChain> chain = uniformChain(model);
  if (!chain || model.gravity.norm() == 0.0) return std::nullopt;
  return twoPinCatenary(model, *chain);
}

std::optional<ClosedFormError> closedFormError(const mysim::Model& model,
                                               const mysim::RunRecord& run) {
  if (run.frames.empty()) return std::nullopt;
  if (model.isCircle()) return circleError(model, run);
  if (auto cantilever = cantileverReference(model)) {
    const auto reading = readCantilever(model, run.frames.back());
    const double exact = cantilever->overhang * cantilever->elastica.drop;
    ClosedFormError e{"cantilever tip drop (heavy elastica)", std::abs(reading->drop - exact), exact};
    e.motion_left = motionLeft(run);
    return e;
  }
  const std::optional<UniformChain> chain = uniformChain(model);
  std::vector<char> only_first_pinned(model.particleCount(), 0);
  if (!only_first_pinned.empty()) only_first_pinned[0] = 1;
  if (!chain || model.gravity.norm() == 0.0 || model.wind || model.pin_motion ||
      !model.colliders.empty()) {
    return std::nullopt;
  }
  std::vector<char> both_ends_pinned(model.particleCount(), 0);
  if (model.particleCount() >= 3) {
    both_ends_pinned.front() = both_ends_pinned.back() = 1;
    if (model.pinned == both_ends_pinned) return twoPinCatenaryError(model, *chain, run);
  }
  if (model.pinned != only_first_pinned) return std::nullopt;
  const double alignment = chain->direction.dot(model.gravity.normalized());
  if (alignment > 1.0 - 1e-12) return chainSagError(model, *chain, run);
  if (chain->particles == 2 && model.drag == 0.0 && chain->damping == 0.0) {
    return pendulumPeriodError(model, *chain, run);
  }
  return std::nullopt;
}

}  // namespace springcheck
