#include "mysim/cloth.h"

#include <algorithm>

namespace mysim {

ClothSpringCounts expectedClothSpringCounts(int rows, int cols) {
  const long r = rows, c = cols;
  return {r * (c - 1) + c * (r - 1), 2 * (r - 1) * (c - 1),
          r * std::max(0L, c - 2) + c * std::max(0L, r - 2)};
}

void buildCloth(const ClothShape& shape, Model& model) {
  const int rows = shape.rows, cols = shape.cols, n = rows * cols;
  const double dx = shape.width / (cols - 1), dy = shape.height / (rows - 1);
  const Vec3 along_row = Vec3::UnitX();
  const Vec3 down_rows = shape.hanging ? Vec3(-Vec3::UnitY()) : Vec3(-Vec3::UnitZ());
  auto index = [cols](int r, int c) { return r * cols + c; };

  model.mass = Vector::Constant(n, shape.particle_mass);
  model.pinned.assign(n, 0);
  model.start_position.resize(3 * n);
  model.start_velocity = Vector::Zero(3 * n);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      at3(model.start_position, index(r, c)) =
          shape.origin + c * dx * along_row + r * dy * down_rows;
    }
  }

  model.springs.clear();
  // Exactly the springs it will hold: the list is the largest part of a model, and growing it by
  // doubling left up to half of it unused (5 MB of a 256 x 256 cloth).
  const ClothSpringCounts counts = expectedClothSpringCounts(rows, cols);
  model.springs.reserve((shape.structural ? counts.structural : 0) +
                        (shape.shear ? counts.shear : 0) + (shape.flex ? counts.flex : 0));
  // Rest lengths are the start distances: the grid starts flat and unstretched.
  auto link = [&](int a, int b, const SpringParameters& p, SpringFamily family) {
    const double rest = (at3(model.start_position, b) - at3(model.start_position, a)).norm();
    model.springs.push_back({a, b, rest, p.stiffness, p.damping, family});
  };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      if (shape.structural) {
        if (c + 1 < cols)
          link(index(r, c), index(r, c + 1), *shape.structural, SpringFamily::Structural);
        if (r + 1 < rows)
          link(index(r, c), index(r + 1, c), *shape.structural, SpringFamily::Structural);
      }
      if (shape.shear && r + 1 < rows && c + 1 < cols) {
        link(index(r, c), index(r + 1, c + 1), *shape.shear, SpringFamily::Shear);
        link(index(r, c + 1), index(r + 1, c), *shape.shear, SpringFamily::Shear);
      }
      if (shape.flex) {
        if (c + 2 < cols) link(index(r, c), index(r, c + 2), *shape.flex, SpringFamily::Flex);
        if (r + 2 < rows) link(index(r, c), index(r + 2, c), *shape.flex, SpringFamily::Flex);
      }
    }
  }
  model.grid = GridShape{rows, cols};
}

}  // namespace mysim
