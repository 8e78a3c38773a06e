#include "compare/metrics/heavy_elastica.h"

#include <array>
#include <cmath>

namespace springcheck {
namespace {

// State in sigma = s / L: theta, theta', x, y (drop).
using ElasticaState = std::array<double, 4>;

ElasticaState integrate(double load, double clamp_curvature) {
  constexpr int kSteps = 5000;  // RK4 error ~ (2e-4)^4 times the load squared: below 1e-12 of L
  const double h = 1.0 / kSteps;
  auto rate = [load](double sigma, const ElasticaState& u) {
    return ElasticaState{u[1], -load * (1.0 - sigma) * std::cos(u[0]), std::cos(u[0]),
                         std::sin(u[0])};
  };
  ElasticaState u{0.0, clamp_curvature, 0.0, 0.0};
  for (int k = 0; k < kSteps; ++k) {
    const double sigma = k * h;
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

}  // namespace

ElasticaTip heavyElastica(double load) {
  // theta'(1) as a function of kappa0 = theta'(0) changes sign on [0, load / 2]: at 0 the strip
  // curls back (theta'' < 0 throughout), at the linear theory's load / 2 the moment it needs,
  // load * integral (1 - s) cos(theta), is at most load / 2. The Illinois variant of regula falsi
  // keeps that bracket and converges superlinearly.
  double a = 0.0, b = 0.5 * load;
  double fa = integrate(load, a)[1], fb = integrate(load, b)[1];
  int side = 0;
  for (int it = 0; it < 200 && fb != 0.0 && std::abs(b - a) > 1e-14 * load; ++it) {
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
  const ElasticaState tip = integrate(load, b);
  ElasticaTip result;
  result.drop = tip[3];
  result.reach = tip[2];
  result.tip_angle = tip[0];
  result.chord_angle = std::atan2(tip[3], tip[2]);
  result.clamp_curvature = b;
  return result;
}

double bendingLengthFromChord(double overhang, double chord_angle) {
  double low = 1e-6, high = kMaxElasticaLoad;  // chords from 1e-5 to 68 degrees
  for (int it = 0; it < 45; ++it) {  // the bracket's ratio to 1 + 1e-12
    const double mid = std::sqrt(low * high);
    (heavyElastica(mid).chord_angle < chord_angle ? low : high) = mid;
  }
  return overhang / std::cbrt(std::sqrt(low * high));
}

}  // namespace springcheck
