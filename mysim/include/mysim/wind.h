#pragma once
#include <cstdint>

#include "mysim/types.h"

namespace mysim {

// Wind as a force per particle in a fixed direction with a random, gusting magnitude (the seed's
// flutter). Randomness comes from a counter-based hash of (seed, particle, gust window), so the
// force is a pure function of time and particle: every RK stage, every re-run and every engine sees
// the same gusts.
struct Wind {
  Vec3 direction = Vec3::UnitZ();  // unit vector
  double strength = 0.0;           // N per affected particle, mean
  double gust = 0.0;         // relative amplitude in [0, 1]: magnitude in strength (1 +- gust)
  double gust_period = 0.1;  // s, the gust magnitude is held this long
  double coverage = 1.0;     // fraction of particles the wind touches in each gust window
  std::uint64_t seed = 1;
};

Vec3 windForce(const Wind& wind, int particle, double t);

}  // namespace mysim
