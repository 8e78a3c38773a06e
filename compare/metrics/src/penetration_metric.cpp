#include "compare/metrics/penetration_metric.h"

#include <algorithm>

namespace springcheck {

Penetration penetration(const std::vector<mysim::Collider>& colliders,
                        Eigen::Ref<const mysim::ParticleRows> positions) {
  Penetration p;
  double total = 0.0;
  for (int i = 0; i < positions.rows(); ++i) {
    const mysim::Vec3 x = positions.row(i).head<3>().transpose();
    double depth = 0.0;
    for (const mysim::Collider& c : colliders) depth = std::max(depth, -signedDistance(c, x));
    if (depth <= 0.0) continue;
    ++p.count;
    total += depth;
    p.deepest = std::max(p.deepest, depth);
  }
  p.mean_depth = p.count ? total / p.count : 0.0;
  return p;
}

std::vector<Penetration> penetrationOverTime(const std::vector<mysim::Collider>& colliders,
                                             const mysim::RunRecord& run) {
  std::vector<Penetration> series;
  for (const mysim::ParticleRows& frame : run.frames) {
    series.push_back(penetration(colliders, frame));
  }
  return series;
}

}  // namespace springcheck
