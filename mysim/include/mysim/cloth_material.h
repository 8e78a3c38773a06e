#pragma once
#include <optional>

#include "mysim/model.h"

namespace mysim {

// The grid a material cloth of `resolution` cells across `width` takes: columns resolution + 1,
// rows so that cells are as square as the height allows (at least one cell). Clamped: one more
// column, the two first ones pinned with the clamp's edge midway between them, and the width
// from that edge to the free end (resolution + 1/2 cells; cloth_material.cpp says why).
struct MaterialGrid {
  int rows = 0, cols = 0;
  double dx = 0.0, dy = 0.0;
};
MaterialGrid materialGrid(double width, double height, int resolution, bool clamped);

// The lattice constants of a grid with structural (k_x along rows, k_y along columns) and
// shear springs k_d on cells dx x dy, for membrane stiffness Y and shear G (small strain,
// homogeneous): C11 = C22 = C with C - G^2 / C = Y, C12 = C66 = G, and
//   k_d = G d^2 / (2 dx dy),  k_x = (C - G dx^2 / dy^2) dy / dx,  k_y = (C - G dy^2 / dx^2) dx / dy
// (d the diagonal). Fails (returns nullopt) where a structural spring would need negative
// stiffness: G too large for the cell's aspect ratio.
struct LatticeSprings {
  double structural_x, structural_y, shear;
};
std::optional<LatticeSprings> latticeSprings(double stretch, double shear, double dx, double dy);

// Replaces the per-spring constants and masses of a cloth built by buildCloth (model.grid set,
// structural and shear families present, flex present iff material.bending == Flex) by the
// material's: lumped masses (density x a quarter of each adjacent cell), lattice springs, hinges
// over the grid's triangles. Returns the drag coefficient the damping rate means (N s/m).
double applyClothMaterial(const ClothMaterial& material, double dx, double dy, Model& model);

}  // namespace mysim
