#include "compare/metrics/drape_metric.h"

#include <cmath>

namespace springcheck {

NodeDistance nodeDistance(const Positions& a, const Positions& b) {
  NodeDistance d;
  double sum = 0.0;
  for (int i = 0; i < a.rows(); ++i) {
    const double di = (a.row(i) - b.row(i)).norm();
    d.per_node.push_back(di);
    sum += di * di;
    if (di > d.max || d.argmax < 0) {
      d.max = di;
      d.argmax = i;
    }
  }
  d.rms = a.rows() ? std::sqrt(sum / a.rows()) : 0.0;
  return d;
}

}  // namespace springcheck
