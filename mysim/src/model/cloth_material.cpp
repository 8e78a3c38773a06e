#include "mysim/cloth_material.h"

#include <algorithm>
#include <cmath>

#include "mysim/cloth_surface.h"

namespace mysim {

const char* bendingModelName(BendingModel model) {
  switch (model) {
    case BendingModel::Hinge:
      return "hinge";
    case BendingModel::Flex:
      return "flex";
    case BendingModel::None:
      break;
  }
  return "none";
}

MaterialGrid materialGrid(double width, double height, int resolution, bool clamped) {
  MaterialGrid g;
  // A clamp holds the first two columns; the line its slope is zero about lies midway between
  // them (finite differences' reflection), so that is the clamp's edge, and the overhang from
  // it to the free end is `width`: resolution + 1/2 cells. Measured (1-D beam of the same
  // energies): the tip drop then converges at second order (0.18 % off at 16 cells), where an
  // edge on the second column gave first order (13 % off at 16 cells).
  g.dx = width / (resolution + (clamped ? 0.5 : 0.0));
  const int row_cells = std::max(1, static_cast<int>(std::lround(height / g.dx)));
  g.dy = height / row_cells;
  g.cols = resolution + 1 + (clamped ? 1 : 0);
  g.rows = row_cells + 1;
  return g;
}

std::optional<LatticeSprings> latticeSprings(double stretch, double shear, double dx, double dy) {
  const double c = 0.5 * (stretch + std::sqrt(stretch * stretch + 4.0 * shear * shear));
  const double d2 = dx * dx + dy * dy;
  LatticeSprings k;
  k.shear = shear * d2 / (2.0 * dx * dy);
  k.structural_x = (c - shear * dx * dx / (dy * dy)) * dy / dx;
  k.structural_y = (c - shear * dy * dy / (dx * dx)) * dx / dy;
  if (!(k.structural_x > 0.0 && k.structural_y > 0.0)) return std::nullopt;
  return k;
}

double applyClothMaterial(const ClothMaterial& material, double dx, double dy, Model& model) {
  const GridShape grid = *model.grid;
  const auto springs = latticeSprings(material.stretch_stiffness, material.shear_stiffness, dx, dy);
  for (Spring& s : model.springs.edit()) {
    switch (s.family) {
      case SpringFamily::Structural: {  // along a row (x) or down a column
        const bool along_row = std::abs(s.j - s.i) == 1;
        s.stiffness = along_row ? springs->structural_x : springs->structural_y;
        // A spring on the sheet's edge stands for half a cell (the lattice's springs each stand
        // for one): half the stiffness, or a strip of R cells stretches as R + 1 (25 % too stiff
        // at 4 cells across).
        const int ri = s.i / grid.cols, ci = s.i % grid.cols, rj = s.j / grid.cols, cj = s.j % grid.cols;
        const bool on_edge = along_row ? (ri == rj && (ri == 0 || ri == grid.rows - 1))
                                       : (ci == cj && (ci == 0 || ci == grid.cols - 1));
        if (on_edge) s.stiffness *= 0.5;
        break;
      }
      case SpringFamily::Shear:
        s.stiffness = springs->shear;
        break;
      case SpringFamily::Flex:
        s.stiffness = material.flex_stiffness;
        break;
      default:
        break;
    }
  }
  // A quarter of every cell to each of its corners: the total is density x area exactly.
  model.mass.setZero(grid.rows * grid.cols);
  const double quarter = 0.25 * material.density * dx * dy;
  for (int r = 0; r + 1 < grid.rows; ++r) {
    for (int c = 0; c + 1 < grid.cols; ++c) {
      for (int p : {r * grid.cols + c, r * grid.cols + c + 1, (r + 1) * grid.cols + c,
                    (r + 1) * grid.cols + c + 1}) {
        model.mass[p] += quarter;
      }
    }
  }
  if (material.bending == BendingModel::Hinge) {
    // Both ways of cutting the cells into triangles, each at half the rigidity: the grid's shear
    // springs cross both diagonals, and one cut alone bends differently about its two diagonals
    // (1 : 3) and clamps one row's edge more firmly than the other's (measured: a 2-cell-wide
    // strip twisted, its tip 37 % lower than the beam's). With both, bending along either grid
    // axis is the continuum's and a cantilever stays level across its width.
    const double half = 0.5 * material.bending_rigidity;
    model.hinges = meshHinges(gridTriangles(grid), model.start_position, half);
    const std::vector<Hinge> other = meshHinges(gridTriangles(grid, true), model.start_position, half);
    model.hinges.insert(model.hinges.end(), other.begin(), other.end());
  }
  model.material = MaterialSource{material, dx, dy, false};
  return material.damping_rate * material.density * dx * dy;
}

}  // namespace mysim
