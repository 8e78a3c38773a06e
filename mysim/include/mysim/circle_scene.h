#pragma once
// A scene of the seed's first-order ODE x' = -y, y' = x (scene_kind.h): no particles, a start
// point.
#include "mysim/scene_kind.h"

namespace mysim {

struct CircleScene : SceneKindBase {
  static constexpr const char* kType = "circle";
  Eigen::Vector2d start{1.0, 0.0};

  void read(FieldReader& system, const std::string& source);
  void build(Model& model) const;
  SystemSize size() const { return {1.0, 0.0}; }
  // Refuses an integrator that needs particles.
  void checkWhole(const IntegratorSettings& integrator) const;
};

}  // namespace mysim
