#include "compare/metrics/sliding_contact.h"

#include <cmath>
#include <sstream>

#include "mysim/collider.h"
#include "mysim/energy.h"

namespace springcheck {
namespace {

// How close to its grown surface a particle must start to count as lying on the plane: far
// below a millimetre margin, far above the rounding of a node put on it (1e-16 of its place).
constexpr double kOnPlane = 1e-9;  // m
// Elastic energy a body may hold at the start and still count as unstressed, per newton of its
// weight: 1e-10 J/N is the energy of lifting it by 0.1 nm, nothing a slide of millimetres sees.
constexpr double kUnstressedPerNewton = 1e-10;  // m
// How alike the particles' start velocities must be to move as one body.
constexpr double kSameVelocity = 1e-12;  // m/s

mysim::Vec3 rowVelocity(const mysim::ParticleRows& frame, int p) {
  return frame.row(p).tail<3>().transpose();
}

// The one plane every particle starts on, if the model has exactly one collider, a plane, and
// no pins.
const mysim::Plane* restingPlane(const mysim::Model& model, const mysim::ParticleRows& first) {
  if (model.colliders.size() != 1) return nullptr;
  const mysim::Plane* plane = std::get_if<mysim::Plane>(&model.colliders.front());
  if (!plane) return nullptr;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) return nullptr;
    const double gap = signedDistance(*plane, mysim::rowPosition(first, p)) - plane->margin;
    if (std::abs(gap) > kOnPlane) return nullptr;
  }
  return plane;
}

// Why the body on the plane is no rigid block under gravity and friction, if it is not.
std::optional<std::string> notABlock(const mysim::Model& model, const mysim::ParticleRows& first,
                                     double pressing) {
  if (model.wind) return std::string("wind acts on the body on the plane: its closed form is for gravity, drag and friction");
  if (model.drag > 0.0) {
    for (int p = 1; p < model.particleCount(); ++p) {
      if (std::abs(model.mass[p] - model.mass[0]) > 1e-12 * model.mass[0]) {
        return std::string("drag on unequal masses slows them unequally: the body deforms, no rigid block");
      }
    }
  }
  if (!(pressing > 0.0)) return std::string("gravity does not press the body onto the plane");
  const int n = model.particleCount();
  mysim::Vector x(3 * n);
  double mass = 0.0;
  for (int p = 0; p < n; ++p) x.segment<3>(3 * p) = mysim::rowPosition(first, p), mass += model.mass[p];
  const mysim::EnergyTerms e = mechanicalEnergy(model, x, mysim::Vector::Zero(3 * n));
  if (e.spring > kUnstressedPerNewton * mass * model.gravity.norm()) {
    return std::string("the body starts stressed (") + std::to_string(e.spring) +
           " J in its springs): it deforms as it slides, no rigid block";
  }
  for (int p = 1; p < n; ++p) {
    if ((rowVelocity(first, p) - rowVelocity(first, 0)).norm() > kSameVelocity) {
      return std::string("the particles start with different velocities: no rigid block");
    }
  }
  return std::nullopt;
}

// Distance along a line after t: start speed u >= 0, then acceleration a less the drag rate k
// times the speed (dv/dt = a - k v; k = 0 without drag), stopping at v = 0 when a < 0, at the time
// returned in `stopped_at`.
double lineDistance(double u, double a, double k, double t, std::optional<double>& stopped_at) {
  if (k == 0.0) {
    if (a < 0.0 && u + a * t <= 0.0) {
      stopped_at = u / -a;
      return u * u / (2.0 * -a);
    }
    return u * t + 0.5 * a * t * t;
  }
  // v(t) = a/k + (u - a/k) e^(-k t); s(t) = (a/k) t + (u - a/k) (1 - e^(-k t)) / k.
  const double terminal = a / k;
  auto distance = [&](double time) { return terminal * time - (u - terminal) * std::expm1(-k * time) / k; };
  if (a < 0.0) {
    const double stop = std::log1p(-u * k / a) / k;
    if (stop <= t) {
      stopped_at = stop;
      return distance(stop);
    }
  }
  return distance(t);
}

mysim::Vec3 fromRest(const SlidingBlock& b, double t) {
  const double pull = b.along_plane.norm();
  if (pull <= b.friction.static_coefficient * b.pressing || t <= 0.0) return mysim::Vec3::Zero();
  std::optional<double> never;
  return lineDistance(0.0, pull - b.friction.kinetic * b.pressing, b.drag_rate, t, never) * (b.along_plane / pull);
}

}  // namespace

mysim::Vec3 slideDisplacement(const SlidingBlock& b, double t) {
  const double u = b.velocity.norm();
  if (u == 0.0) return fromRest(b, t);
  const mysim::Vec3 e = b.velocity / u;
  std::optional<double> stopped_at;
  const double s = lineDistance(u, b.along_plane.dot(e) - b.friction.kinetic * b.pressing, b.drag_rate, t, stopped_at);
  if (!stopped_at) return s * e;
  return s * e + fromRest(b, t - *stopped_at);
}

std::optional<ClosedFormResult> slidingError(const mysim::Model& model, const mysim::RunRecord& run) {
  const mysim::ParticleRows& first = run.frames.front();
  const mysim::Plane* plane = restingPlane(model, first);
  if (!plane) return std::nullopt;
  const double pressing = -model.gravity.dot(plane->normal);
  if (auto why = notABlock(model, first, pressing)) return std::unexpected(*why);
  auto centroid = [&](const mysim::ParticleRows& frame) {
    mysim::Vec3 c = mysim::Vec3::Zero();
    double mass = 0.0;
    for (int p = 0; p < model.particleCount(); ++p) c += model.mass[p] * mysim::rowPosition(frame, p), mass += model.mass[p];
    return mysim::Vec3(c / mass);
  };
  SlidingBlock block{centroid(first), rowVelocity(first, 0), model.gravity + pressing * plane->normal,
                     pressing, plane->friction, model.drag / model.mass[0]};
  block.velocity -= block.velocity.dot(plane->normal) * plane->normal;
  const double u = block.velocity.norm(), pull = block.along_plane.norm();
  if (u > 0.0 && pull > 1e-12 * model.gravity.norm() &&
      block.velocity.cross(block.along_plane).norm() > 1e-9 * u * pull) {
    return std::unexpected("the body moves across the slope: a two-dimensional slide, no closed form here");
  }
  double worst = 0.0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const mysim::Vec3 exact = block.start + slideDisplacement(block, run.times[f] - run.times.front());
    worst = std::max(worst, (centroid(run.frames[f]) - exact).norm());
  }
  const double distance = slideDisplacement(block, run.times.back() - run.times.front()).norm();
  const bool sticks = distance == 0.0;
  return ClosedFormError{
      .quantity = sticks ? "rest on a plane (static friction holds)" : "sliding distance on a plane",
      .error = worst,
      .exact = distance,
      .motion_left = std::nullopt};
}

}  // namespace springcheck
