#include "compare/metrics/settled_quantities.h"

#include <algorithm>

namespace springcheck {

SettledQuantities settledQuantities(const mysim::Model& model, const EngineRun& run,
                                    const EngineMetrics& end) {
  const mysim::RunRecord& r = run.record;
  SettledQuantities out;
  if (r.blowup || r.frames.size() < 2 || r.times.size() != r.frames.size()) return out;
  // The earlier frame: the last one at or before 0.9 T (T the last frame's time).
  const double at = 0.9 * r.times.back();
  const auto after = std::upper_bound(r.times.begin(), r.times.end(), at);
  const std::size_t earlier = std::max<std::ptrdiff_t>(1, after - r.times.begin()) - 1;
  // Only the shape metrics are read, so the earlier record carries frames alone (no energies:
  // nothing of them is needed, and the copy stays small).
  mysim::RunRecord truncated;
  truncated.engine = r.engine;
  truncated.integrator = r.integrator;
  truncated.dt = r.dt;
  truncated.times.assign(r.times.begin(), r.times.begin() + earlier + 1);
  truncated.frames.assign(r.frames.begin(), r.frames.begin() + earlier + 1);
  const EngineMetrics before = engineMetrics(model, {run.engine, truncated});
  for (const MetricInfo& info : metricCatalog()) {
    if (!info.refined || info.pair) continue;
    const auto last = metricValue(end, info.name);
    const auto first = metricValue(before, info.name);
    if (last && first) out[info.name] = {*last, *first};
  }
  return out;
}

}  // namespace springcheck
