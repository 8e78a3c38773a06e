#include "compare/studies/physical_reference.h"

#include <cmath>
#include <numbers>

#include "compare/io/text_format.h"
#include "compare/metrics/cantilever_metric.h"
#include "compare/metrics/elastic_catenary.h"
#include "compare/studies/refinement.h"

namespace springcheck {
namespace {

PhysicalReference exact(std::string_view quantity, double value, const std::string& source) {
  PhysicalReference r;
  r.quantity = quantity;
  r.value = value;
  r.closed_form = true;
  r.source = source + " (closed form)";
  return r;
}

// A material chain (the one kind whose ends carry half a link's mass) pinned at its two ends,
// level under gravity: the continuous elastic catenary's midspan sag.
std::optional<double> levelCableSag(const mysim::Scene& scene) {
  const auto* chain = std::get_if<mysim::ChainScene>(&scene.system);
  if (!chain || chain->end_mass == 0.0) return std::nullopt;
  const mysim::ChainShape& c = chain->shape;
  const double g = scene.gravity.norm();
  if (g == 0.0 || std::abs(c.direction.normalized().dot(scene.gravity / g)) > 1e-12 ||
      chain->start.pins != std::vector<int>{0, c.particles - 1}) {
    return std::nullopt;
  }
  const int links = c.particles - 1;
  const ElasticCatenary cable =
      levelElasticCatenary(c.spacing * links, c.rest_length * links,
                           c.particle_mass / c.rest_length * g, c.stiffness * c.rest_length);
  if (cable.horizontal_tension == 0.0) return std::nullopt;
  return cable.midspan_sag;
}

}  // namespace

std::optional<PhysicalReference> closedFormReference(const mysim::Scene& scene,
                                                     const mysim::Model& model,
                                                     std::string_view quantity) {
  if (auto c = cantileverReference(model)) {
    if (quantity == "tip_drop") return exact(quantity, c->elastica.drop * c->overhang, "heavy elastica");
    if (quantity == "chord_angle") {
      return exact(quantity, c->elastica.chord_angle * 180.0 / std::numbers::pi, "heavy elastica");
    }
    if (quantity == "bending_length" && c->load <= kLargestReadableLoad) {
      return exact(quantity, c->chord_bending_length, "heavy elastica read by Peirce's chord");
    }
  }
  if (quantity == "sag_lowest") {
    if (auto sag = levelCableSag(scene)) return exact(quantity, *sag, "continuous elastic catenary");
  }
  return std::nullopt;
}

PhysicalReference refinementReference(std::string_view quantity, const std::vector<int>& resolutions,
                                      const std::vector<double>& values, const std::string& of) {
  PhysicalReference r;
  r.quantity = quantity;
  const RefinementEstimate finest = estimateRefinement(resolutions, values);
  r.order = finest.order;
  if (!finest.limit) {
    r.reason = "no limit: " + finest.reason;
    return r;
  }
  r.value = finest.limit;
  r.uncertainty = 1.25 * std::abs(values.back() - *finest.limit);
  r.source = "Richardson limit of " + of;
  if (!finest.order) {
    r.warning = finest.reason;
    return r;
  }
  r.source += ", order " + formatNumber(*finest.order, 3);
  if (values.size() >= 4) {
    const std::vector<int> n(resolutions.begin(), resolutions.end() - 1);
    const std::vector<double> q(values.begin(), values.end() - 1);
    const RefinementEstimate coarser = estimateRefinement(n, q);
    r.coarser_order = coarser.order;
    if (!coarser.order) {
      r.warning = "the coarser three give no order (" + coarser.reason + ")";
    } else if (std::abs(*coarser.order - *finest.order) >
               kOrderAgreement * std::max(*coarser.order, *finest.order)) {
      r.warning = "orders disagree: " + formatNumber(*coarser.order, 2) + " then " +
                  formatNumber(*finest.order, 2);
    }
    if (coarser.order) r.source += " (" + formatNumber(*coarser.order, 3) + " from the coarser three)";
  }
  return r;
}

}  // namespace springcheck
