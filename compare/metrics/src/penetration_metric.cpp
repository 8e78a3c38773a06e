#include "compare/metrics/penetration_metric.h"

#include <algorithm>

namespace springcheck {

Penetration penetration(const mysim::Sphere& sphere, const mysim::ParticleRows& frame) {
  Penetration p;
  double total = 0.0;
  for (int i = 0; i < frame.rows(); ++i) {
    const double depth =
        sphere.radius - (frame.row(i).head<3>().transpose() - sphere.center).norm();
    if (depth <= 0.0) continue;
    ++p.count;
    total += depth;
    p.deepest = std::max(p.deepest, depth);
  }
  p.mean_depth = p.count ? total / p.count : 0.0;
  return p;
}

std::vector<Penetration> penetrationOverTime(const mysim::Sphere& sphere,
                                             const mysim::RunRecord& run) {
  std::vector<Penetration> series;
  for (const mysim::ParticleRows& frame : run.frames) series.push_back(penetration(sphere, frame));
  return series;
}

}  // namespace springcheck
