#pragma once
#include <Eigen/Core>

#include "mysim/model.h"

namespace viewer {

// Draws one static collider in the current GL context (lighting on) from the quads its shape
// gives (mysim::surfaceMesh): the viewer names no shape. `rows` is the engine's state (x y z vx
// vy vz per particle): an endless shape is drawn under it, and every shape inset by as much as
// the cloth's flat triangles cut into it, so it does not show through them.
void drawCollider(const mysim::Collider& collider, const mysim::Model& model,
                  const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows);

}  // namespace viewer
