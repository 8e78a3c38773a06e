#include "compare/metrics/heavy_elastica.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>

namespace springcheck {
namespace {

// State in sigma = s / L: theta, theta', x, y (drop).
using ElasticaState = std::array<double, 4>;

// Fourth-order Runge-Kutta: `steps` steps of h from sigma0 (h < 0 runs towards the clamp).
template <typename Rate>
ElasticaState rk4(const Rate& rate, ElasticaState u, double sigma0, double h, int steps) {
  for (int k = 0; k < steps; ++k) {
    const double sigma = sigma0 + k * h;  // sigma0 = 0: exactly k h
    const ElasticaState k1 = rate(sigma, u);
    ElasticaState v;
    for (int i = 0; i < 4; ++i) v[i] = u[i] + 0.5 * h * k1[i];
    const ElasticaState k2 = rate(sigma + 0.5 * h, v);
    for (int i = 0; i < 4; ++i) v[i] = u[i] + 0.5 * h * k2[i];
    const ElasticaState k3 = rate(sigma + 0.5 * h, v);
    for (int i = 0; i < 4; ++i) v[i] = u[i] + h * k3[i];
    const ElasticaState k4 = rate(sigma + h, v);
    for (int i = 0; i < 4; ++i) u[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return u;
}

ElasticaState integrate(double load, double clamp_curvature) {
  constexpr int kSteps = 5000;  // RK4 error ~ (2e-4)^4 times the load squared: below 1e-12 of L
  const double h = 1.0 / kSteps;
  auto rate = [load](double sigma, const ElasticaState& u) {
    return ElasticaState{u[1], -load * (1.0 - sigma) * std::cos(u[0]), std::cos(u[0]),
                         std::sin(u[0])};
  };
  return rk4(rate, ElasticaState{0.0, clamp_curvature, 0.0, 0.0}, 0.0, h, kSteps);
}

// The root of theta'(1) = 0 over kappa0 = theta'(0) in [a, b], where it changes sign, by the
// Illinois variant of regula falsi (keeps the bracket, converges superlinearly).
double rootInBracket(double load, double a, double b) {
  double fa = integrate(load, a)[1], fb = integrate(load, b)[1];
  int side = 0;
  for (int it = 0; it < 200 && fb != 0.0 && std::abs(b - a) > 1e-14 * std::max(load, b); ++it) {
    const double c = b - fb * (b - a) / (fb - fa);
    const double fc = integrate(load, c)[1];
    if ((fc > 0.0) == (fb > 0.0)) {
      b = c, fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = b, fa = fb;
      b = c, fb = fc;
      side = +1;
    }
  }
  return b;
}

// theta'(0) L at load <= kMaxElasticaLoad: the one root in [0, load / 2]. At 0 the strip curls
// back (theta'' < 0 throughout); at the linear theory's load / 2 the moment it needs,
// load * integral (1 - s) cos(theta), is at most load / 2.
double bracketedClampCurvature(double load) { return rootInBracket(load, 0.0, 0.5 * load); }

// Past kMaxElasticaLoad shooting from the clamp is ill-conditioned (a heavy strip's tail hangs
// near vertical, where theta'(1) swings between branches over a per cent of theta'(0)), so the
// strip is shot from its free end instead, in delta = pi/2 - theta (the tail's tiny tilt, which
// theta itself cannot resolve near pi/2):
//   delta'' = load (1 - sigma) sin(delta),   delta(1) = delta1,   delta'(1) = 0,
// integrated back to the clamp, where delta(0) must be pi/2 (level). While delta stays below pi/2
// it grows backwards and grows with delta1, so delta(0) rises monotonically with delta1 and the
// root is one, found by bisection on log(delta1). Reach and drop are the integrals of sin(delta)
// and cos(delta) along the way. Steps grow with sqrt(load) to resolve the clamp's bend, whose
// length is load^(-1/2).
struct FromTip {
  double clamp_delta, clamp_curvature, reach, drop;
};

FromTip integrateFromTip(double load, double delta1) {
  const int steps = static_cast<int>(5000 * std::max(1.0, std::sqrt(load / kMaxElasticaLoad)));
  const double h = -1.0 / steps;
  auto rate = [load](double sigma, const ElasticaState& u) {  // delta, delta', reach, drop
    return ElasticaState{u[1], load * (1.0 - sigma) * std::sin(u[0]), std::sin(u[0]),
                         std::cos(u[0])};
  };
  const ElasticaState u = rk4(rate, ElasticaState{delta1, 0.0, 0.0, 0.0}, 1.0, h, steps);
  // Integrated from 1 down to 0: the sums are minus the clamp-to-tip integrals; theta' = -delta'.
  return {u[0], -u[1], -u[2], -u[3]};
}

ElasticaTip heavyElasticaFromTip(double load) {
  const double level = 0.5 * std::numbers::pi;
  auto short_of_level = [&](double log_delta) {
    return integrateFromTip(load, std::exp(log_delta)).clamp_delta < level;
  };
  // delta(0) ~ delta1 exp((2/3) sqrt(load)) (WKB): start below that, step down until short.
  // Then up in half steps to the first tilt that reaches level: a larger one may curl past pi/2
  // on the way back and cross level again on another branch.
  double low = -(2.0 / 3.0) * std::sqrt(load) - 5.0;
  while (!short_of_level(low) && low > -700.0) low -= 10.0;
  double high = low + 0.5;
  while (short_of_level(high) && high < std::log(level)) low = high, high += 0.5;
  for (int it = 0; it < 100 && high - low > 1e-15 * std::abs(low); ++it) {
    const double mid = 0.5 * (low + high);
    (short_of_level(mid) ? low : high) = mid;
  }
  const double delta1 = std::exp(0.5 * (low + high));
  const FromTip f = integrateFromTip(load, delta1);
  ElasticaTip result;
  result.drop = f.drop;
  result.reach = f.reach;
  result.tip_angle = level - delta1;
  result.chord_angle = std::atan2(f.drop, f.reach);
  result.clamp_curvature = f.clamp_curvature;
  return result;
}

}  // namespace

ElasticaTip heavyElastica(double load) {
  if (load > kMaxElasticaLoad) return heavyElasticaFromTip(load);
  const double b = bracketedClampCurvature(load);
  const ElasticaState tip = integrate(load, b);
  ElasticaTip result;
  result.drop = tip[3];
  result.reach = tip[2];
  result.tip_angle = tip[0];
  result.chord_angle = std::atan2(tip[3], tip[2]);
  result.clamp_curvature = b;
  return result;
}

namespace {

// The load whose elastica has this chord. Each costs 45 elastica solves (about 0.1 s), and one
// run's metrics read the same chord several times (the reading, the closed form's, the settled
// quantities'), so answers are kept: the same chord gives the same bits either way.
double loadFromChord(double chord_angle) {
  static std::mutex guard;
  static std::map<double, double> known;
  {
    const std::lock_guard lock(guard);
    if (auto it = known.find(chord_angle); it != known.end()) return it->second;
  }
  // Chords up to 68 degrees on loads 1e-6 .. 30, steeper ones on 30 .. 1e4 (89.2 degrees).
  static const double steepest_bracketed = heavyElastica(kMaxElasticaLoad).chord_angle;
  double low = 1e-6, high = kMaxElasticaLoad;
  if (chord_angle > steepest_bracketed) low = kMaxElasticaLoad, high = kLargestReadableLoad;
  for (int it = 0; it < 45; ++it) {  // the bracket's ratio to 1 + 1e-12
    const double mid = std::sqrt(low * high);
    (heavyElastica(mid).chord_angle < chord_angle ? low : high) = mid;
  }
  const double load = std::sqrt(low * high);
  const std::lock_guard lock(guard);
  if (known.size() > 4096) known.clear();  // a bound on memory; long studies read many chords
  known[chord_angle] = load;
  return load;
}

}  // namespace

double bendingLengthFromChord(double overhang, double chord_angle) {
  return overhang / std::cbrt(loadFromChord(chord_angle));
}

}  // namespace springcheck
