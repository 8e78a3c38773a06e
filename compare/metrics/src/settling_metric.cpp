#include "compare/metrics/settling_metric.h"

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
  mysim::Vector x;
  for (const mysim::ParticleRows& frame : run.frames) {
    x.resize(3 * frame.rows());
    for (int p = 0; p < frame.rows(); ++p) x.segment<3>(3 * p) = mysim::rowPosition(frame, p);
    worst = std::max(worst, mysim::maxSpringStrain(model.springs, x));
  }
  return worst;
}

}  // namespace springcheck
