#pragma once
// A run starts with every free particle outside every collider. The after-step moves a particle
// that crossed a surface in one step out through the nearest face (docs/scenes.md); a cloth
// placed across a box's inside would have whole rows pushed onto one face, nodes landing on one
// another (zero-length springs: a NaN at the first step). So such a start is refused, naming the
// particle, the collider and the depth, before anything runs.
#include <optional>

#include "mysim/model.h"
#include "mysim/limit_error.h"

namespace mysim {

std::optional<LimitError> checkStartOutsideColliders(const Model& model);

}  // namespace mysim
