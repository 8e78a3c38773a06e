#include "mysim/run_limits.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mysim {

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * page : 8e9;
}

std::optional<LimitError> checkRunLimits(double particles, double springs, const RunSettings& run) {
  auto text = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  if (!std::isfinite(run.duration) || !(run.duration > 0)) {
    return LimitError{"integrator.duration",
                      "expected a finite number > 0, got " + text(run.duration)};
  }
  if (!std::isfinite(run.dt) || !(run.dt > 0)) {
    return LimitError{"integrator.dt", "expected a finite number > 0, got " + text(run.dt)};
  }
  if (run.dt > run.duration) {
    return LimitError{"integrator.dt", "a step no longer than the duration (" + text(run.dt) +
                                           " s > " + text(run.duration) + " s)"};
  }
  const double steps = run.duration / run.dt;
  if (!(steps <= kMaxSteps)) {
    return LimitError{"integrator.dt", text(run.dt) + " s gives " + text(steps) + " steps over " +
                                           text(run.duration) + " s; at most " + text(kMaxSteps) +
                                           " (see mysim/run_limits.h)"};
  }
  if (!std::isfinite(run.sample_interval) || run.sample_interval < 0) {
    return LimitError{"output.sample_interval",
                      "expected a finite number >= 0, got " + text(run.sample_interval)};
  }
  // Bytes: ~30 state-sized vectors of integrator buffers (6 doubles a particle), ~2 adjacency
  // entries and a parameter triple a spring, and the sampled trajectory (6 doubles a particle a
  // frame; about 200 frames unless a sample interval is given).
  const double frames =
      (run.sample_interval > 0 ? std::min(steps, run.duration / run.sample_interval) : 200.0) + 2;
  const double need = particles * (30 * 48 + frames * 48) + springs * 64;
  const double have = physicalMemoryBytes();
  if (need > 0.5 * have) {
    std::ostringstream m;
    m.precision(3);
    m << particles << " particles, " << springs << " springs and " << frames
      << " frames need about " << need / (1 << 30) << " GiB, more than half of this machine's "
      << have / (1 << 30) << " GiB";
    return LimitError{"system", m.str()};
  }
  return std::nullopt;
}

}  // namespace mysim
