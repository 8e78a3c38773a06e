#include "compare/metrics/closed_form.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "compare/metrics/cantilever_metric.h"
#include "compare/metrics/capstan.h"
#include "compare/metrics/sliding_contact.h"

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

// Whether the springs join particle p to p + 1 for every p and nothing else (in any spring
// order): a chain whatever the scene called it (a "chain", or a particle list laid out as one).
bool isIndexOrderedPath(const mysim::Model& model) {
  const int n = model.particleCount();
  if (static_cast<int>(model.springs.size()) != n - 1) return false;
  std::vector<char> link(n, 0);  // link[p]: the spring p - p + 1 seen
  for (const mysim::Spring& s : model.springs) {
    const int low = std::min(s.i, s.j);
    if (std::abs(s.i - s.j) != 1 || link[low]) return false;
    link[low] = 1;
  }
  return true;
}

namespace {

ClosedFormResult circleError(const mysim::Model& model, const mysim::RunRecord& run) {
  double worst = 0.0;
  const Eigen::Vector2d s = *model.circle_start;
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
  if (model.isCircle() || model.springs.empty() || !isIndexOrderedPath(model)) return std::nullopt;
  const mysim::Spring& s0 = model.springs.front();
  for (const mysim::Spring& s : model.springs) {
    if (s.rest_length != s0.rest_length || s.stiffness != s0.stiffness || s.damping != s0.damping) {
      return std::nullopt;
    }
  }
  for (int p = 1; p < model.particleCount(); ++p) {  // a pin's own mass does not matter
    if (!model.pinned[p] && model.mass[p] != model.mass[1]) return std::nullopt;
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

ClosedFormResult chainSagError(const mysim::Model& model, const UniformChain& c,
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

ClosedFormResult pendulumPeriodError(const mysim::Model& model, const UniformChain& c,
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
  if (crossings.size() < 2) {
    return std::unexpected("the bob crossed below its pin fewer than twice: too short a run to time a "
                           "period (run it longer)");
  }
  const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  return ClosedFormError{"pendulum period", std::abs(measured / period - 1.0), period, std::nullopt, "rel"};
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

ClosedFormResult twoPinCatenaryError(const mysim::Model& model, const UniformChain& c,
                                                   const mysim::RunRecord& run) {
  const auto nodes = twoPinCatenary(model, c);
  if (!nodes) {
    return std::unexpected("the two pins are one above the other (or the catenary's tension did not "
                           "converge): no catenary to compare with");
  }
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


// The damped oscillator: a chain of two, particle 0 pinned, no gravity, the bob started at the
// spring's rest length with a velocity v0 along it. Its stretch x obeys m x'' + c x' + k x = 0
// (spring damping acts along the spring), x(0) = 0, x'(0) = v0, with w0 = sqrt(k / m) and
// zeta = c / (2 sqrt(k m)):
//   under  x = v0 / wd e^(-zeta w0 t) sin(wd t),  wd = w0 sqrt(1 - zeta^2)
//   critical (|zeta - 1| < 1e-9)  x = v0 t e^(-w0 t)
//   over   x = v0 / (r1 - r2) (e^(r1 t) - e^(r2 t)),  r = -w0 (zeta -+ sqrt(zeta^2 - 1)).
// The error is the largest |x(t) - exact| over the frames, m.
double dampedOscillator(double w0, double zeta, double v0, double t) {
  if (std::abs(zeta - 1.0) < 1e-9) return v0 * t * std::exp(-w0 * t);
  if (zeta < 1.0) {
    const double wd = w0 * std::sqrt(1.0 - zeta * zeta);
    return v0 / wd * std::exp(-zeta * w0 * t) * std::sin(wd * t);
  }
  const double root = std::sqrt(zeta * zeta - 1.0);
  const double r1 = -w0 * (zeta - root), r2 = -w0 * (zeta + root);
  return v0 / (r1 - r2) * (std::exp(r1 * t) - std::exp(r2 * t));
}

ClosedFormResult dampedOscillatorError(const mysim::Model& model, const UniformChain& c,
                                                     const mysim::RunRecord& run) {
  const mysim::Vec3 v0 = mysim::at3(model.start_velocity, 1);
  const double along = v0.dot(c.direction);
  if ((v0 - along * c.direction).norm() > 1e-12 * std::max(1.0, v0.norm()) || model.drag != 0.0) {
    return std::unexpected("an oscillator with drag, or started moving across its spring, leaves the "
                           "one-dimensional m x'' + c x' + k x = 0 the closed form solves");
  }
  const double w0 = std::sqrt(c.stiffness / c.particle_mass);
  const double zeta = c.damping / (2.0 * std::sqrt(c.stiffness * c.particle_mass));
  double worst = 0.0, peak = 0.0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const double x = (run.frames[f].row(1).head<3>().transpose() - c.origin).dot(c.direction) -
                     c.rest_length;
    const double exact = dampedOscillator(w0, zeta, along, run.times[f]);
    worst = std::max(worst, std::abs(x - exact));
    peak = std::max(peak, std::abs(exact));
  }
  const char* regime = std::abs(zeta - 1.0) < 1e-9 ? "critically damped"
                       : zeta < 1.0                ? "underdamped"
                                                   : "overdamped";
  return ClosedFormError{std::string(regime) + " oscillator", worst, peak};
}

// A taut chain: N free masses m between two pins, springs of stiffness k stretched to spacing a
// (tension T = k (a - rest)), no gravity, started with velocities across the line. Small
// transverse motion is a sum of modes j = 1..N, shapes phi_j(i) = sin(j pi i / (N + 1)),
// frequencies w_j = 2 sqrt(T / (m a)) sin(j pi / (2 (N + 1))) (the beaded string; exact for the
// linearised discrete system, Rayleigh, "The theory of sound", sec. 120). The mode the start
// velocity loads most is followed: its modal coordinate's upward zero crossings, linearly
// interpolated between frames, give the measured frequency; the error is relative.
ClosedFormResult tautChainModeError(const mysim::Model& model, const UniformChain& c,
                                                  const mysim::RunRecord& run) {
  const int free = c.particles - 2;
  const mysim::Vec3 first = mysim::at3(model.start_position, 0);
  const mysim::Vec3 last = mysim::at3(model.start_position, c.particles - 1);
  const double a = (last - first).norm() / (c.particles - 1);
  const double tension = c.stiffness * (a - c.rest_length);
  if (!(tension > 0.0) || c.damping != 0.0 || model.drag != 0.0) {
    return std::unexpected("a chain between two pins without gravity has mode frequencies only when "
                           "stretched (tension > 0) and undamped");
  }
  const mysim::Vec3 line = (last - first).normalized();
  // The transverse direction: that of the start velocities.
  mysim::Vec3 across = mysim::Vec3::Zero();
  for (int i = 1; i <= free; ++i) across += mysim::at3(model.start_velocity, i);
  across -= across.dot(line) * line;
  if (across.norm() == 0.0) {
    return std::unexpected("a taut chain started without velocity across its line does not oscillate");
  }
  across.normalize();
  auto shape = [&](int j, int i) { return std::sin(j * std::numbers::pi * i / (free + 1)); };
  int mode = 1;
  double loaded = 0.0;
  for (int j = 1; j <= free; ++j) {
    double q = 0.0;
    for (int i = 1; i <= free; ++i) q += shape(j, i) * mysim::at3(model.start_velocity, i).dot(across);
    if (std::abs(q) > loaded) loaded = std::abs(q), mode = j;
  }
  const double exact = 2.0 * std::sqrt(tension / (c.particle_mass * a)) *
                       std::sin(mode * std::numbers::pi / (2.0 * (free + 1)));
  std::vector<double> crossings;
  double previous = 0.0;
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    double q = 0.0;
    for (int i = 1; i <= free; ++i) {
      q += shape(mode, i) * (run.frames[f].row(i).head<3>().transpose() - first).dot(across);
    }
    if (f > 0 && previous < 0.0 && q >= 0.0) {
      crossings.push_back(run.times[f - 1] + (run.times[f] - run.times[f - 1]) * previous / (previous - q));
    }
    previous = q;
  }
  if (crossings.size() < 3) {
    return std::unexpected("the mode crossed zero fewer than three times: too short a run to time "
                           "its frequency (run it longer)");
  }
  const double measured =
      2.0 * std::numbers::pi * (crossings.size() - 1) / (crossings.back() - crossings.front());
  return ClosedFormError{"taut chain, mode " + std::to_string(mode) + " frequency",
                         std::abs(measured / exact - 1.0), exact, std::nullopt, "rel"};
}
}  // namespace

std::optional<std::vector<mysim::Vec3>> twoPinCatenaryNodes(const mysim::Model& model) {
  const std::optional<UniformChain> chain = uniformChain(model);
  if (!chain || model.gravity.norm() == 0.0) return std::nullopt;
  return twoPinCatenary(model, *chain);
}

namespace {

// Why a model that is no uniform chain has no closed form (the cantilever is tried before).
std::string notAChain(const mysim::Model& model, const mysim::RunRecord& run) {
  if (readCantilever(model, run.frames.back())) {
    return model.hinges.empty()
               ? "a clamped strip bent by flex springs has no bending rigidity to put in the "
                 "elastica (hinge bending has one)"
               : "the strip's load w L^3 / B is past the elastica's solved range (1e6)";
  }
  if (model.springs.empty()) return "free particles without springs: no closed form";
  if (isIndexOrderedPath(model)) return "a chain of unequal springs or unequal masses";
  return "the suite has closed forms only for the circle, a uniform chain (hanging, between two "
         "pins, a pendulum, an oscillator, a taut line) and a clamped strip with hinge bending";
}

// The closed forms of a uniform chain without gravity: the oscillator and the taut chain.
ClosedFormResult weightlessChainError(const mysim::Model& model, const UniformChain& chain,
                                      const mysim::RunRecord& run,
                                      const std::vector<char>& only_first_pinned,
                                      const std::vector<char>& both_ends_pinned) {
  if (model.particleCount() == 2 && model.pinned == only_first_pinned) {
    return dampedOscillatorError(model, chain, run);
  }
  if (model.particleCount() >= 3 && model.pinned == both_ends_pinned) {
    return tautChainModeError(model, chain, run);
  }
  return std::unexpected("without gravity a chain has a closed form pinned at its first particle "
                         "(two particles: the oscillator) or at both ends (the taut chain) only");
}

}  // namespace

ClosedFormResult closedFormError(const mysim::Model& model, const mysim::RunRecord& run) {
  if (run.frames.empty()) return std::unexpected("the run recorded no frame");
  if (run.blowup) {
    std::ostringstream why;
    why << "the run blew up at t = " << run.blowup->time
        << " s: a closed form judges a whole run, not its last healthy frame";
    return std::unexpected(why.str());
  }
  if (model.isCircle()) return circleError(model, run);
  if (auto sliding = slidingError(model, run)) return *sliding;
  if (auto capstan = capstanError(model, run)) return *capstan;
  if (auto cantilever = cantileverReference(model)) {
    const auto reading = readCantilever(model, run.frames.back());
    const double exact = cantilever->overhang * cantilever->elastica.drop;
    ClosedFormError e{"cantilever tip drop (heavy elastica)", std::abs(reading->drop - exact), exact};
    e.motion_left = motionLeft(run);
    return e;
  }
  const std::optional<UniformChain> chain = uniformChain(model);
  if (!chain) return std::unexpected(notAChain(model, run));
  if (model.wind || model.pin_motion || !model.colliders.empty()) {
    return std::unexpected(std::string(model.wind ? "wind" : model.pin_motion ? "driven pins" : "a collider") +
                           " acts on the chain: its closed forms hold without wind, pin motion "
                           "and colliders");
  }
  std::vector<char> only_first_pinned(model.particleCount(), 0);
  only_first_pinned[0] = 1;
  std::vector<char> both_ends_pinned(model.particleCount(), 0);
  if (model.particleCount() >= 3) both_ends_pinned.front() = both_ends_pinned.back() = 1;
  if (model.gravity.norm() == 0.0) {
    return weightlessChainError(model, *chain, run, only_first_pinned, both_ends_pinned);
  }
  if (model.particleCount() >= 3 && model.pinned == both_ends_pinned) {
    return twoPinCatenaryError(model, *chain, run);
  }
  if (model.pinned != only_first_pinned) {
    return std::unexpected("a chain under gravity has a closed form pinned at its first particle or "
                           "at both ends only");
  }
  const double alignment = chain->direction.dot(model.gravity.normalized());
  if (alignment > 1.0 - 1e-12) return chainSagError(model, *chain, run);
  if (chain->particles == 2) {
    if (model.drag == 0.0 && chain->damping == 0.0) return pendulumPeriodError(model, *chain, run);
    return std::unexpected("a damped pendulum has no closed-form period (the rigid pendulum's is "
                           "undamped)");
  }
  return std::unexpected("a chain of several links released off the vertical swings with no "
                         "closed form (chaotically: compare it by energy, not by trajectory)");
}

}  // namespace springcheck
