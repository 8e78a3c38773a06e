#include "compare/metrics/heavy_elastica.h"

#include <array>
#include <cmath>

namespace springcheck {
namespace {

// State in sigma = s / L: theta, theta', x, y (drop).
using ElasticaState = std::array<double, 4>;

ElasticaState integrate(double load, double clamp_curvature) {
  constexpr int kSteps = 20'000;
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
  // Secant on theta'(1)(kappa0) = 0 from the linear theory's kappa0 = load / 2 and a point
  // below it (the large-deflection curvature is smaller: cos(theta) < 1 unloads the clamp).
  double a = 0.5 * load, b = 0.45 * load;
  double fa = integrate(load, a)[1], fb = integrate(load, b)[1];
  for (int it = 0; it < 100 && fb != 0.0 && std::abs(b - a) > 1e-15 * std::abs(b); ++it) {
    const double c = b - fb * (b - a) / (fb - fa);
    a = b, fa = fb;
    b = c, fb = integrate(load, b)[1];
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

double peirceBendingLength(double overhang, double chord_angle) {
  return overhang * std::cbrt(std::cos(0.5 * chord_angle) / (8.0 * std::tan(chord_angle)));
}

}  // namespace springcheck
