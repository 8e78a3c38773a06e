#pragma once
#include <optional>

#include "mysim/model.h"

namespace mysim {

struct SpringParameters {
  double stiffness = 0.0;  // N/m
  double damping = 0.0;    // N s/m
};

// An n x m grid of particles (index = row * cols + col) spanning width x height, with up to three
// spring families: structural (4 grid neighbours), shear (both diagonals of every cell), flex (two
// apart along rows and columns). An absent family adds no springs.
struct ClothShape {
  int rows = 14;
  int cols = 14;
  double width = 1.0;           // m, along the columns (x)
  double height = 1.0;          // m, along the rows
  double particle_mass = 0.01;  // kg
  bool hanging = false;  // false: rows run along -z (a horizontal sheet); true: along -y (vertical)
  Vec3 origin = Vec3::Zero();  // position of particle (0, 0)
  std::optional<SpringParameters> structural, shear, flex;
};

// Counts per family for an n x m grid (the topology test checks these against the builder).
struct ClothSpringCounts {
  long structural, shear, flex;
};
ClothSpringCounts expectedClothSpringCounts(int rows, int cols);

void buildCloth(const ClothShape& shape, Model& model);

}  // namespace mysim
