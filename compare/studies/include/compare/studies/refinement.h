#pragma once
// Convergence under mesh refinement: from a quantity measured at three or more resolutions, the
// observed order of convergence and the Richardson-extrapolated limit (Roache, "Verification and
// validation in computational science and engineering", 1998, ch. 5: the grid convergence
// study). With cell size h = 1 / n and q(h) = q0 + C h^p, the last three values give p from
//   (q1 - q2) / (q2 - q3) = (h1^p - h2^p) / (h2^p - h3^p)
// (solved by bisection for any ratios between resolutions; log(.)/log(r) when the ratio r is
// constant) and q0 = q3 + (q3 - q2) h3^p / (h2^p - h3^p).
#include <optional>
#include <string>
#include <vector>

namespace springcheck {

struct RefinementEstimate {
  // Absent when the successive differences do not shrink in one direction (not yet in the
  // asymptotic range, or not converging): the reason says which.
  std::optional<double> order;
  std::optional<double> limit;
  std::string reason;
};

// `resolutions` increasing (cells across), `values` the quantity at each; at least three.
RefinementEstimate estimateRefinement(const std::vector<int>& resolutions,
                                      const std::vector<double>& values);

}  // namespace springcheck
