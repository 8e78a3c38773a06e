#pragma once
// A scene of a chain (a rope, a cable): its shape given directly, or from a material, a length
// and a resolution (scene_kind.h; docs/materials.md).
#include <optional>

#include "mysim/chain.h"
#include "mysim/scene_kind.h"

namespace mysim {

struct ChainScene : SceneKindBase {
  static constexpr const char* kType = "chain";
  ChainShape shape;
  HangingStart start;
  double end_mass = 0.0;  // a material chain's end particles (half a link), kg; 0: as the rest
  std::optional<double> damping_drag;  // N s/m a material chain's damping rate means

  void read(FieldReader& system, const std::string& source);
  void build(Model& model) const;
  SystemSize size() const { return {double(shape.particles), double(shape.particles - 1)}; }
  void checkWhole(const IntegratorSettings&) const { start.checkSomethingMoves(size().particles); }
  std::optional<double> materialDrag() const { return damping_drag; }

 private:
  void readMaterial(FieldReader& system);
};

}  // namespace mysim
