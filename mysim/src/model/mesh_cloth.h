#pragma once
// A cloth built from a triangle mesh and its material. (A cloth model's surface, whatever built
// it, is cloth_surface.h.)
#include <expected>
#include <string>

#include "mysim/material.h"
#include "mysim/model.h"
#include "mysim/triangle_mesh.h"

namespace mysim {

// A cloth from a triangle mesh and its material (docs/materials.md): a particle per vertex with
// a third of each adjacent triangle's mass, a spring per edge with Van Gelder's form
//   k_e = Y sum_{T at e} A_T / |e|^2
// (the constant fixed by the equilateral lattice, exact there: Y = 2 k / sqrt(3), Poisson's ratio
// 1/3, the only one a triangle lattice of springs has), and with hinge bending a hinge per
// interior edge (hinge.h). The mesh must be flat for hinges (their rest state); not with flex
// bending (skip-one springs need a grid). Returns the drag the damping rate means: rate times
// the mean particle mass. Errors say what is wrong with the mesh.
std::expected<double, std::string> buildMeshCloth(const TriangleMesh& mesh,
                                                  const ClothMaterial& material, const Vec3& origin,
                                                  Model& model);

}  // namespace mysim
