#pragma once
// Round-off or a real difference? Any engine's sensitivity to round-off, measured the same way
// for mysim, Bullet and a user's engine: the run again from a start moved by a few ulps (every
// free particle's coordinates, each by `ulps` units in the last place, signs from a fixed hash so
// the nudge is no rigid motion), and how far apart the two runs drift, frame by frame. A scene
// that amplifies round-off (an undamped swinging chain, a stiff XPBD cloth in float32 at many
// substeps) drifts by orders of magnitude; a damped one stays at its nudge. Two engines whose
// difference stays within what each one's own nudged run drifts are apart by round-off
// amplification, not by their physics (docs/external-engines.md, "Round-off or a real
// difference?").
#include <expected>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"

namespace springcheck {

struct RoundoffSensitivity {
  std::string engine;
  int ulps = 0;
  std::vector<double> times;       // s, the frames both runs sampled
  std::vector<double> divergence;  // m, max node distance between the run and its nudged twin
  double nudge = 0.0;              // m, the largest start displacement the nudge made
  double final_divergence = 0.0;   // m, at the last frame
  double largest_divergence = 0.0; // m, over the run
  // The drift's e-folding rate, 1/s, from a least-squares line through log(divergence) over the
  // frames where it is above the nudge's thousandth (0: it did not grow); the amplification is
  // largest_divergence / nudge.
  double growth_rate = 0.0;
  double amplification = 0.0;
  mysim::RunRecord run;  // the run from the start as given
};

// The model nudged by `ulps` ulps at every free particle's start coordinates.
mysim::Model nudgedModel(const mysim::Model& model, int ulps);

std::expected<RoundoffSensitivity, EngineError> measureRoundoff(const EngineRegistry& registry,
                                                                const std::string& engine,
                                                                const mysim::Model& model,
                                                                const RunConfig& config, int ulps);

// What a difference between two engines is, against their round-off sensitivities: "identical"
// (0 at every frame), "round-off amplification" (at every frame within 10 times the larger of
// the two drifts, and the drifts themselves grew: the scene amplifies round-off), "round-off"
// (within 10 times the drifts, which stayed at the nudge's size), or "real" (past that at some
// frame: the worst one's time). A declared float32 engine's precision floor (twice the two
// floors) is allowed too: its states are no more precise than that.
struct DifferenceVerdict {
  std::string verdict;
  double largest_difference = 0.0;  // m
  double worst_ratio = 0.0;         // difference / (10 x drift) at the worst frame
  double worst_time = 0.0;          // s
};
DifferenceVerdict classifyDifference(const std::vector<double>& difference,
                                     const RoundoffSensitivity& a, const RoundoffSensitivity& b);

}  // namespace springcheck
