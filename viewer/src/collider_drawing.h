#pragma once
#include <Eigen/Core>

#include "mysim/model.h"

namespace viewer {

// Draws one static collider in the current GL context (lighting on), one function per shape;
// `rows` is the engine's state (x y z vx vy vz per particle), which a sphere needs to be drawn
// where the cloth's flat triangles will not hide it.
void drawCollider(const mysim::Collider& collider, const mysim::Model& model,
                  const Eigen::Matrix<double, Eigen::Dynamic, 6>& rows);

}  // namespace viewer
