#include "compare/metrics/capstan.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "mysim/collider.h"

namespace springcheck {
namespace {

// How close to its grown surface a particle must start to count as touching the capstan: far
// below a link, far above the rounding of a node put on it.
constexpr double kTouching = 1e-6;  // m
// How much heavier than every other particle each end mass must be.
constexpr double kEndMassFactor = 10.0;


// The one collider with friction, if it is the only one and a sphere.
const mysim::Sphere* frictionSphere(const mysim::Model& model) {
  const mysim::Sphere* found = nullptr;
  for (const mysim::Collider& c : model.colliders) {
    if (!mysim::colliderFriction(c).any()) continue;
    if (found || !std::holds_alternative<mysim::Sphere>(c)) return nullptr;
    found = &std::get<mysim::Sphere>(c);
  }
  return found;
}

bool heavyEnds(const mysim::Model& model) {
  const int n = model.particleCount();
  double interior = 0.0;
  for (int p = 1; p + 1 < n; ++p) interior = std::max(interior, model.mass[p]);
  return model.mass[0] >= kEndMassFactor * interior && model.mass[n - 1] >= kEndMassFactor * interior;
}

}  // namespace

double Capstan::ratio() const { return std::exp(mu * wrap); }

double Capstan::holdingLoad(const mysim::Model& model) const {
  return ratio() * (model.mass[hold] + hold_side) - load_side;
}

std::optional<Capstan> capstanOf(const mysim::Model& model, const mysim::ParticleRows& first) {
  if (model.isCircle() || model.gravity.norm() == 0.0 || model.particleCount() < 4) return std::nullopt;
  if (!isIndexOrderedPath(model) || !heavyEnds(model)) return std::nullopt;
  if (std::any_of(model.pinned.begin(), model.pinned.end(), [](char p) { return p != 0; })) return std::nullopt;
  const mysim::Sphere* sphere = frictionSphere(model);
  if (!sphere) return std::nullopt;
  const int n = model.particleCount();
  int first_touch = -1, last_touch = -1;
  for (int p = 0; p < n; ++p) {
    const double gap = (mysim::rowPosition(first, p) - sphere->center).norm() - (sphere->radius + sphere->margin);
    if (gap > kTouching) continue;
    if (first_touch < 0) first_touch = p;
    else if (p != last_touch + 1) return std::nullopt;  // two separate runs of contact
    last_touch = p;
  }
  if (first_touch < 1 || last_touch > n - 2) return std::nullopt;
  const mysim::Vec3 in = (mysim::rowPosition(first, first_touch) - mysim::rowPosition(first, first_touch - 1)).normalized();
  const mysim::Vec3 out = (mysim::rowPosition(first, last_touch + 1) - mysim::rowPosition(first, last_touch)).normalized();
  Capstan c;
  c.wrap = std::acos(std::clamp(in.dot(out), -1.0, 1.0));
  c.mu = sphere->friction.static_coefficient;
  c.down = model.gravity.normalized();
  const bool last_is_load = model.mass[n - 1] >= model.mass[0];
  c.hold = last_is_load ? 0 : n - 1;
  c.load = last_is_load ? n - 1 : 0;
  // In a chain at rest on frictionless supports the tension grows by its weight per length times
  // the height it climbs (T = T_end + w g dy): the tension entering and leaving the capstan is
  // the end's weight plus the chain's weight over the height between them.
  double interior_mass = 0.0, length = 0.0;
  for (int p = 1; p + 1 < n; ++p) interior_mass += model.mass[p];
  for (const mysim::Spring& s : model.springs) length += s.rest_length;
  const double per_length = interior_mass / length;
  auto heightAbove = [&](int contact, int end) {
    return std::max(0.0, (mysim::rowPosition(first, end) - mysim::rowPosition(first, contact)).dot(c.down));
  };
  const double before = per_length * heightAbove(first_touch, 0);
  const double after = per_length * heightAbove(last_touch, n - 1);
  c.hold_side = last_is_load ? before : after;
  c.load_side = last_is_load ? after : before;
  return c;
}

double loadDriftOverLastHalf(const Capstan& capstan, const mysim::RunRecord& run) {
  const double half = 0.5 * (run.times.front() + run.times.back());
  std::size_t from = 0;
  while (from + 1 < run.times.size() && run.times[from] < half) ++from;
  double drift = 0.0;
  for (std::size_t f = from; f < run.frames.size(); ++f) {
    const mysim::Vec3 moved = mysim::rowPosition(run.frames[f], capstan.load) - mysim::rowPosition(run.frames[from], capstan.load);
    drift = std::max(drift, std::abs(moved.dot(capstan.down)));
  }
  return drift;
}

std::optional<ClosedFormResult> capstanError(const mysim::Model& model, const mysim::RunRecord& run) {
  const std::optional<Capstan> capstan = capstanOf(model, run.frames.front());
  if (!capstan) return std::nullopt;
  const double holding = capstan->holdingLoad(model), load = model.mass[capstan->load];
  std::ostringstream what;
  what.precision(4);
  what << "capstan holds (load " << load << " kg of the " << holding << " kg e^(mu phi) holds, phi "
       << capstan->wrap * 180.0 / std::numbers::pi << " deg)";
  if (load > holding) {
    std::ostringstream why;
    why.precision(4);
    why << "the load (" << load << " kg) is past the largest the capstan holds, e^(mu phi) (M + strand) - strand = "
        << holding << " kg: it slips, which has no closed form here (springcheck capstan measures the largest "
        << "load that holds)";
    return std::unexpected(why.str());
  }
  return ClosedFormError{what.str(), loadDriftOverLastHalf(*capstan, run), 0.0};
}

}  // namespace springcheck
