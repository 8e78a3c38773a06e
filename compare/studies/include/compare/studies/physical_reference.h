#pragma once
// What a settled quantity of a material scene should be: its physical reference. The closed form
// where the scene has one (the heavy elastica for a clamped strip, the continuous elastic
// catenary for a level cable), otherwise the Richardson limit of a refinement, with the
// uncertainty and the trust its observed orders give it (docs/trade.md).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/studies/refinement.h"
#include "mysim/model.h"
#include "mysim/scene.h"

namespace springcheck {

struct PhysicalReference {
  std::string quantity;
  std::optional<double> value;  // absent: no reference (the reason says why)
  // Same unit as the value: 0 for a closed form; for a limit, Roache's grid convergence index
  // with its safety factor 1.25 for a three-grid study with a measured order:
  // 1.25 |q_finest - limit|.
  double uncertainty = 0.0;
  bool closed_form = false;
  std::optional<double> order;           // the observed order from the finest three
  std::optional<double> coarser_order;   // from the three before, with four or more resolutions
  std::string source;   // "heavy elastica (closed form)", "Richardson limit of ..."
  std::string warning;  // why a limit is not to be trusted (empty: nothing found)
  std::string reason;   // why there is no value
};

// The closed form of `quantity` for this scene at any resolution, or nothing: tip_drop,
// chord_angle (deg) and bending_length of a level clamped strip with hinge bending (the heavy
// elastica, cantilever_metric.h); sag_lowest of a material chain pinned at both ends, level (the
// continuous elastic catenary, elastic_catenary.h).
std::optional<PhysicalReference> closedFormReference(const mysim::Scene& scene,
                                                     const mysim::Model& model,
                                                     std::string_view quantity);

// The limit of `values` at increasing `resolutions` (three or more): order and limit from the
// finest three (refinement.h); with four or more, the order of the three before too. Untrusted
// (warning) when the two orders differ by more than kOrderAgreement of the larger, or the values
// do not converge monotonically; no value when the finest three give no order.
PhysicalReference refinementReference(std::string_view quantity, const std::vector<int>& resolutions,
                                      const std::vector<double>& values, const std::string& of);

}  // namespace springcheck
