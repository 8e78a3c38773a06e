#include "compare/studies/refinement.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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

namespace {
bool ordersAgree(double a, double b) { return std::abs(a - b) <= kOrderAgreement * std::max(a, b); }
std::string orderText(double p) {
  std::ostringstream out;
  out.precision(3);
  out << p;
  return out.str();
}
}  // namespace

RefinementVerdict refinementVerdict(const std::vector<int>& resolutions,
                                    const std::vector<double>& values,
                                    std::optional<double> expected_order) {
  const RefinementEstimate finest = estimateRefinement(resolutions, values);
  const std::string not_converged = "not converged at these resolutions: ";
  if (!finest.order) return {false, not_converged + finest.reason};
  const std::string observed = "observed order " + orderText(*finest.order);
  if (values.size() >= 4) {
    const RefinementEstimate coarser = estimateRefinement(
        std::vector<int>(resolutions.begin(), resolutions.end() - 1),
        std::vector<double>(values.begin(), values.end() - 1));
    if (coarser.order && ordersAgree(*coarser.order, *finest.order)) {
      return {true, "converged: " + observed + ", the coarser triple's " + orderText(*coarser.order)};
    }
    if (!expected_order) {
      return {false, not_converged + observed + ", the coarser triple's " +
                         (coarser.order ? orderText(*coarser.order) : "none (" + coarser.reason + ")")};
    }
  }
  if (!expected_order) {
    return {false, not_converged + observed + " from three resolutions, with no expected order "
                                   "to hold it to: four or more would show it"};
  }
  const std::string against = observed + " (expected " + orderText(*expected_order) + ")";
  if (ordersAgree(*finest.order, *expected_order)) return {true, "converged: " + against};
  return {false, not_converged + against};
}

}  // namespace springcheck
