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

// Two observed orders agree when they differ by at most this fraction of the larger: measured
// on the shipped cantilever (hinge bending, second order), the triples 4-8-16 and 8-16-32 give
// orders within 0.2 of each other and 4-8-16 gives 2.10 against the expected 2; a
// pre-asymptotic sequence (the flex model's, whose "limit" is no bending at all) gives orders
// 0.3 and 1.9, and the Cusick drape's 4-8-16 gives 1.31 where its finer runs (24, 32 rings)
// still move away from that limit.
constexpr double kOrderAgreement = 0.3;

// Whether an estimate carries the evidence a limit or an order needs before a table, a page or
// a finding quotes it: four or more resolutions whose last two triples give orders that agree
// (kOrderAgreement), or three whose order agrees with the discretisation's expected one. Three
// points always fit some order and some limit; only a second triple, or theory, says the fit
// is in the asymptotic range. Otherwise the verdict says "not converged at these resolutions"
// and why (the observed order, what it was held against).
struct RefinementVerdict {
  bool converged = false;
  std::string text;  // "converged at order 2.10 (expected 2)", "not converged at ...: ..."
};
RefinementVerdict refinementVerdict(const std::vector<int>& resolutions,
                                    const std::vector<double>& values,
                                    std::optional<double> expected_order);

}  // namespace springcheck
