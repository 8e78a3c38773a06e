#include "compare/studies/refinement.h"

#include <cmath>

namespace springcheck {

RefinementEstimate estimateRefinement(const std::vector<int>& resolutions,
                                      const std::vector<double>& values) {
  RefinementEstimate e;
  const std::size_t n = values.size();
  if (n < 3 || resolutions.size() != n) {
    e.reason = "fewer than three resolutions";
    return e;
  }
  const double h1 = 1.0 / resolutions[n - 3], h2 = 1.0 / resolutions[n - 2],
               h3 = 1.0 / resolutions[n - 1];
  const double d12 = values[n - 3] - values[n - 2], d23 = values[n - 2] - values[n - 1];
  if (d23 == 0.0) {
    e.order.reset();
    e.limit = values[n - 1];
    e.reason = "the last two values are equal";
    return e;
  }
  const double ratio = d12 / d23;
  if (!(ratio > 0.0)) {
    e.reason = "the differences change sign: not in the asymptotic range";
    return e;
  }
  // g(p) = (h1^p - h2^p) / (h2^p - h3^p) grows with p from log(h1/h2)/log(h2/h3) at p -> 0.
  auto g = [&](double p) {
    return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
  };
  double low = 1e-3, high = 12.0;
  if (!(ratio > g(low))) {
    e.reason = "the differences do not shrink: not converging at these resolutions";
    return e;
  }
  if (ratio > g(high)) {
    e.reason = "the differences shrink faster than order 12: round-off or exact";
    return e;
  }
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (low + high);
    (g(mid) < ratio ? low : high) = mid;
  }
  const double p = 0.5 * (low + high);
  e.order = p;
  e.limit = values[n - 1] - d23 * std::pow(h3, p) / (std::pow(h2, p) - std::pow(h3, p));
  return e;
}

}  // namespace springcheck
