#include "compare/settling_metric.h"

#include <algorithm>
#include <cmath>

namespace springcheck {

std::optional<double> settlingTime(const mysim::RunRecord& run, double relative_threshold) {
  if (run.energies.empty()) return std::nullopt;
  double peak = 0.0;
  for (const mysim::EnergyTerms& e : run.energies) peak = std::max(peak, e.kinetic);
  const double threshold = relative_threshold * peak;
  if (run.energies.back().kinetic > threshold) return std::nullopt;
  std::size_t f = run.energies.size() - 1;
  while (f > 0 && run.energies[f - 1].kinetic <= threshold) --f;
  return run.times[f];
}

double maxStrainOverRun(const mysim::Model& model, const mysim::RunRecord& run) {
  double worst = 0.0;
  for (const mysim::ParticleRows& frame : run.frames) {
    for (const mysim::Spring& s : model.springs) {
      const double l = (frame.row(s.j).head<3>() - frame.row(s.i).head<3>()).norm();
      worst = std::max(worst, std::abs(l / s.rest_length - 1.0));
    }
  }
  return worst;
}

}  // namespace springcheck
