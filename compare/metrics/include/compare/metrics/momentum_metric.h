#pragma once
#include <optional>

#include "mysim/model.h"
#include "mysim/simulation.h"

namespace springcheck {

// How far a run's linear and angular momentum wander from their start (Erez, Tassa and Todorov
// 2015 measure them beside energy). Only where the model conserves them: nothing outside acts on
// the particles but uniform gravity (no pins, drag, wind or colliders). Springs act along the line
// between their ends, equal and opposite, so they conserve both; uniform gravity changes the
// linear momentum by exactly M g t (which is taken off) and leaves the angular momentum about the
// centre of mass alone.
struct MomentumDrift {
  // max over frames of |P(t) - P(0) - M g t| / P_ref, P_ref = max over frames of sum m |v|
  // (the momentum the motion carries: P itself is often 0, a spinning body at rest).
  double linear = 0.0;
  // max over frames of |L(t) - L(0)| / L_ref, L about the centre of mass, L_ref = max over
  // frames of sum m |r - c| |v - v_c|.
  double angular = 0.0;
};

// Nothing when the model does not conserve momentum, or nothing moves.
std::optional<MomentumDrift> momentumDrift(const mysim::Model& model, const mysim::RunRecord& run);

// Whether nothing but uniform gravity acts on the model from outside.
bool conservesMomentum(const mysim::Model& model);

}  // namespace springcheck
