#include "compare/metrics/elastic_catenary.h"

#include <cmath>

namespace springcheck {

ElasticCatenary levelElasticCatenary(double span, double length, double weight, double axial) {
  const double v = 0.5 * weight * length;
  // x(L0) grows with H from 0 (H -> 0: the cable hangs straight down, both halves) without
  // bound (stretch), so bisection on H in log space brackets the one root.
  auto reach = [&](double h) { return h * length / axial + 2.0 * h / weight * std::asinh(v / h); };
  double low = 1e-12 * weight * length, high = 1.0;
  while (reach(high) < span) high *= 2.0;
  if (reach(low) >= span) return {};
  for (int it = 0; it < 200 && high - low > 1e-15 * high; ++it) {
    const double mid = 0.5 * (low + high);
    (reach(mid) < span ? low : high) = mid;
  }
  const double h = 0.5 * (low + high);
  ElasticCatenary c;
  c.horizontal_tension = h;
  const double s = 0.5 * length;
  c.midspan_sag = (v * s - 0.5 * weight * s * s) / axial +
                  h / weight * (std::sqrt(1.0 + (v / h) * (v / h)) - 1.0);
  return c;
}

}  // namespace springcheck
