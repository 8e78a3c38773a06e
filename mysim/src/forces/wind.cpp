#include "mysim/wind.h"

#include <cmath>

namespace mysim {
namespace {

// SplitMix64 finaliser: a cheap, well-mixed hash, so the "random" gusts need no generator state.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform in [0, 1) from (seed, particle, window, salt).
double uniform(std::uint64_t seed, int particle, long window, std::uint64_t salt) {
  std::uint64_t h = mix(seed ^ mix(static_cast<std::uint64_t>(particle) ^
                                   mix(static_cast<std::uint64_t>(window) ^ mix(salt))));
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

}  // namespace

Vec3 windForce(const Wind& wind, int particle, double t) {
  const long window = static_cast<long>(std::floor(t / wind.gust_period));
  if (wind.coverage < 1.0 && uniform(wind.seed, particle, window, 1) >= wind.coverage) {
    return Vec3::Zero();
  }
  const double u = uniform(wind.seed, particle, window, 2);
  return wind.strength * (1.0 + wind.gust * (2.0 * u - 1.0)) * wind.direction;
}

}  // namespace mysim
