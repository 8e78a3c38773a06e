#pragma once
#include "reference/bullet_engine.h"

namespace reference {

// Mass shared by every free particle, or 0 if they differ.
double uniformFreeMass(const mysim::Model& model);

// The parameters of btDeformableMassSpringForce, when one instance of it can hold every spring of
// the model: one stiffness for the non-bending links, one for the bending (flex) links, one
// damping for all (addForce merges forces by type, so there can be only one).
struct UniformSprings {
  double stiffness = 0.0, bending_stiffness = -1.0, damping = 0.0;
};
std::optional<UniformSprings> uniformSprings(const mysim::Model& model);

}  // namespace reference
