#pragma once
// A scene of a cloth (scene_kind.h): a grid with its springs given directly, a grid from a
// material and a resolution, or a triangle mesh from a material (docs/materials.md).
#include <optional>

#include "mysim/cloth.h"
#include "mysim/cloth_material.h"
#include "mysim/scene_kind.h"
#include "mysim/triangle_mesh.h"

namespace mysim {

struct ClothScene : SceneKindBase {
  static constexpr const char* kType = "cloth";
  ClothShape shape;  // a grid's (a mesh cloth uses its origin alone)
  HangingStart start;
  std::optional<ClothMaterial> material;  // cloth from its material
  MaterialGrid material_grid;             // its grid, when material is set and mesh is not
  bool material_clamped = false;          // pins "left_clamp"
  std::optional<TriangleMesh> mesh;       // a mesh cloth (with material)
  double mesh_drag = 0.0;                 // N s/m a mesh cloth's damping rate means

  void read(FieldReader& system, const std::string& source);
  void build(Model& model) const;
  SystemSize size() const;
  void checkWhole(const IntegratorSettings&) const { start.checkSomethingMoves(size().particles); }
  std::optional<double> materialDrag() const;
  bool bendsByHinges() const { return material && material->bending == BendingModel::Hinge; }
  std::vector<std::string> warnings() const { return mesh ? mesh->warnings : std::vector<std::string>{}; }

 private:
  void readGrid(FieldReader& system);
  void readMaterialGrid(FieldReader& system);
  void readMesh(FieldReader& system, const std::string& source);
};

}  // namespace mysim
