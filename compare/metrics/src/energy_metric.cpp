#include "compare/metrics/energy_metric.h"

#include <algorithm>
#include <cmath>

namespace springcheck {

EnergyDrift energyDrift(const std::vector<mysim::EnergyTerms>& energies) {
  EnergyDrift d;
  if (energies.empty()) return d;
  const mysim::EnergyTerms& e0 = energies.front();
  d.reference = std::abs(e0.total());
  for (const mysim::EnergyTerms& e : energies) d.reference = std::max(d.reference, e.kinetic);
  const double ref = d.reference > 0 ? d.reference : 1.0;
  // The total less the work put in from outside: what damping alone may only lower.
  auto net = [](const mysim::EnergyTerms& e) { return e.total() - e.external_work; };
  double lowest = net(e0);
  for (const mysim::EnergyTerms& e : energies) {
    d.kinetic.push_back((e.kinetic - e0.kinetic) / ref);
    d.gravity.push_back((e.gravity - e0.gravity) / ref);
    d.spring.push_back((e.spring - e0.spring) / ref);
    d.total.push_back((e.total() - e0.total()) / ref);
    d.max_abs_total = std::max(d.max_abs_total, std::abs(d.total.back()));
    d.max_rise = std::max(d.max_rise, net(e) - lowest);
    lowest = std::min(lowest, net(e));
  }
  return d;
}

}  // namespace springcheck
