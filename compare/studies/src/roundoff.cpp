#include "compare/studies/roundoff.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "compare/metrics/drape_metric.h"

namespace springcheck {
namespace {

// +1 or -1 from a fixed hash of the coordinate's index (splitmix64's finaliser).
double nudgeSign(std::uint64_t index) {
  std::uint64_t z = index + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return ((z ^ (z >> 31)) & 1) ? 1.0 : -1.0;
}

// x moved by `ulps` units in its last place, up or down.
double moved(double x, int ulps, double sign) {
  for (int k = 0; k < ulps; ++k) x = std::nextafter(x, sign * INFINITY);
  return x;
}

// Slope of log(d) against t over the frames where d is above `floor`: least squares.
double logSlope(const std::vector<double>& t, const std::vector<double>& d, double floor) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t f = 0; f < t.size(); ++f) {
    if (!(d[f] > floor)) continue;
    const double y = std::log(d[f]);
    n += 1, st += t[f], sy += y, stt += t[f] * t[f], sty += t[f] * y;
  }
  const double det = n * stt - st * st;
  return n >= 3 && det > 0 ? std::max(0.0, (n * sty - st * sy) / det) : 0.0;
}

}  // namespace

mysim::Model nudgedModel(const mysim::Model& model, int ulps) {
  // ulps of the coordinate, or of the scene's size where the coordinate is smaller (an ulp of
  // 0 is 5e-324 m: no nudge at all, and a subnormal coordinate).
  double size = 0.0;
  for (int i = 0; i < model.start_position.size(); ++i) {
    size = std::max(size, std::abs(model.start_position[i]));
  }
  mysim::Model nudged = model;
  for (int p = 0; p < model.particleCount(); ++p) {
    if (model.pinned[p]) continue;
    for (int c = 0; c < 3; ++c) {
      const int i = 3 * p + c;
      const double x = model.start_position[i];
      const double base = std::max(std::abs(x), size);
      nudged.start_position[i] = x + (moved(base, ulps, nudgeSign(i)) - base);
    }
  }
  return nudged;
}

std::expected<RoundoffSensitivity, EngineError> measureRoundoff(const EngineRegistry& registry,
                                                                const std::string& engine,
                                                                const mysim::Model& model,
                                                                const RunConfig& config, int ulps) {
  auto plain = registry.run(engine, model, config);
  if (!plain) return std::unexpected(plain.error());
  const mysim::Model nudged = nudgedModel(model, ulps);
  auto twin = registry.run(engine, nudged, config);
  if (!twin) return std::unexpected(twin.error());
  RoundoffSensitivity s;
  s.engine = engine;
  s.ulps = ulps;
  for (int i = 0; i < model.start_position.size(); ++i) {
    s.nudge = std::max(s.nudge, std::abs(nudged.start_position[i] - model.start_position[i]));
  }
  const std::size_t frames = std::min(plain->frames.size(), twin->frames.size());
  for (std::size_t f = 0; f < frames; ++f) {
    s.times.push_back(plain->times[f]);
    s.divergence.push_back(
        nodeDistance(plain->frames[f].leftCols<3>(), twin->frames[f].leftCols<3>()).max);
  }
  s.run = std::move(*plain);
  if (frames == 0) return s;
  s.final_divergence = s.divergence.back();
  s.largest_divergence = *std::max_element(s.divergence.begin(), s.divergence.end());
  s.amplification = s.nudge > 0 ? s.largest_divergence / s.nudge : 0.0;
  s.growth_rate = logSlope(s.times, s.divergence, 1e-3 * s.nudge);
  return s;
}

DifferenceVerdict classifyDifference(const std::vector<double>& difference,
                                     const RoundoffSensitivity& a, const RoundoffSensitivity& b) {
  DifferenceVerdict v;
  const std::size_t frames =
      std::min({difference.size(), a.divergence.size(), b.divergence.size()});
  for (std::size_t f = 0; f < frames; ++f) {
    v.largest_difference = std::max(v.largest_difference, difference[f]);
    // The drift a frame may hold: ten times the larger twin's, and never below the nudge (the
    // twins start that far apart).
    // A float32 engine's states are only that precise (its declared floor, half an ulp of float).
    const double allowed =
        std::max(10.0 * std::max({a.divergence[f], b.divergence[f], a.nudge, b.nudge}),
                 2.0 * (a.run.precision_floor + b.run.precision_floor));
    const double ratio = difference[f] / allowed;
    if (ratio > v.worst_ratio) v.worst_ratio = ratio, v.worst_time = a.times[f];
  }
  if (v.largest_difference == 0.0) {
    v.verdict = "identical";
  } else if (v.worst_ratio > 1.0) {
    v.verdict = "real";
  } else {
    // Amplified: either twin drifted to 100 times its nudge or more.
    v.verdict = std::max(a.amplification, b.amplification) >= 100.0 ? "round-off amplification"
                                                                    : "round-off";
  }
  return v;
}

}  // namespace springcheck
