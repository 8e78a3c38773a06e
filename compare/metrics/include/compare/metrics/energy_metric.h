#pragma once
#include <vector>

#include "mysim/energy.h"

namespace springcheck {

// Energy drift per frame, each term apart: (E(t) - E(0)) / E_ref. The textbook E(0) is often 0
// here (a cloth starting at rest at height 0), so E_ref = max(|E(0)|, peak kinetic energy): the
// energy the motion actually carries.
struct EnergyDrift {
  double reference = 0.0;  // E_ref, J
  std::vector<double> kinetic, gravity, spring, total;
  double max_abs_total = 0.0;  // max |total drift|
  // Largest rise of (total - external work) above its lowest earlier value, in J: wind and
  // moving pins are accounted for, so a damped scene must not rise beyond round-off and the
  // integrator's own error, whatever drives it.
  double max_rise = 0.0;
};
// A run without energies (none recorded) gives empty series: its drift metrics are not
// applicable (null), never a zero that reads as perfect conservation.
EnergyDrift energyDrift(const std::vector<mysim::EnergyTerms>& energies);

}  // namespace springcheck
