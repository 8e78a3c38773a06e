#include "compare/metrics/sag_metric.h"

#include <algorithm>

namespace springcheck {

SagSeries sagOverTime(const mysim::Model& model, const mysim::RunRecord& run) {
  const mysim::Vec3 down =
      model.gravity.norm() > 0 ? mysim::Vec3(model.gravity.normalized()) : mysim::Vec3(0, -1, 0);
  const int n = model.particleCount();
  std::vector<int> pins, middle;
  for (int p = 0; p < n; ++p) {
    if (model.pinned[p]) pins.push_back(p);
  }
  if (model.grid) {
    const int row = model.grid->rows - 1, cols = model.grid->cols;
    middle = {row * cols + (cols - 1) / 2, row * cols + cols / 2};  // same node when cols is odd
  } else if (model.springs.size() + 1 == static_cast<std::size_t>(n) && n > 1) {
    middle = {n - 1};  // a chain: its far end
  }
  double start_top = 0.0;
  for (int p = 0; p < n; ++p) {
    const double depth = down.dot(mysim::at3(model.start_position, p));
    start_top = p == 0 ? depth : std::min(start_top, depth);
  }

  SagSeries sag;
  for (const mysim::ParticleRows& frame : run.frames) {
    auto depth = [&](int p) { return down.dot(mysim::rowPosition(frame, p)); };
    double pin_level = start_top;
    if (!pins.empty()) {
      pin_level = 0.0;
      for (int p : pins) pin_level += depth(p) / pins.size();
    }
    double lowest = depth(0);
    for (int p = 1; p < n; ++p) lowest = std::max(lowest, depth(p));
    sag.lowest.push_back(lowest - pin_level);
    if (!middle.empty()) {
      double mid = 0.0;
      for (int p : middle) mid += depth(p) / middle.size();
      sag.free_middle.push_back(mid - pin_level);
    }
  }
  return sag;
}

}  // namespace springcheck
