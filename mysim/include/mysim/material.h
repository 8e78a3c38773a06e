#pragma once
// What a cloth is made of, independent of its resolution (cloth_material.h maps it to springs,
// hinges and masses).

namespace mysim {

// A cloth described by its material instead of its springs: what it is, independent of the
// resolution it is simulated at. docs/materials.md derives every mapping below and cites it.
enum class BendingModel {
  Hinge,  // hinge bending (hinge.h) from the rigidity: converges as the mesh is refined
  Flex,   // skip-one springs of a fixed per-spring stiffness: what most cloth codes do
  None,   // no bending energy: a membrane (what an ablation takes bending out to)
};
const char* bendingModelName(BendingModel model);

struct ClothMaterial {
  double density = 0.0;            // kg/m^2
  double stretch_stiffness = 0.0;  // N/m: uniaxial membrane stiffness (Young's modulus x thickness)
  double shear_stiffness = 0.0;    // N/m: the lattice's in-plane shear modulus x thickness
  BendingModel bending = BendingModel::Hinge;
  double bending_rigidity = 0.0;   // N m, Hinge: B = E t^3 / 12 (1 - nu^2)
  double flex_stiffness = 0.0;     // N/m, Flex: every flex spring's, at any resolution
  double damping_rate = 0.0;       // 1/s: drag per unit mass (scene.drag = rate x an interior mass)
};

// What a model built from a material came from: the closed forms and refinement read it.
struct MaterialSource {
  ClothMaterial material;
  double dx = 0.0, dy = 0.0;  // m, the grid's cell
  bool clamped = false;       // the left edge in a clamp one cell deep (pins "left_clamp")
};

}  // namespace mysim
