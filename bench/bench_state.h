#pragma once

namespace bench {

// The triad's best bandwidth in bytes/s, measured first in the same run (registration order).
inline double& measuredBandwidth() {
  static double bandwidth = 0.0;
  return bandwidth;
}

}  // namespace bench
