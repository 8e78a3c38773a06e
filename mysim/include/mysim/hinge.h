#pragma once
#include <array>
#include <vector>

#include "mysim/types.h"

namespace mysim {

// Bending across one interior edge of a triangle mesh that is flat at rest: the quadratic
// (isometric) bending model of Bergou, Wardetzky, Harmon, Zorin and Grinspun, "A quadratic
// bending model for inextensible surfaces" (SGP 2006), written per hinge. Particles: the edge
// (0, 1) and the two vertices opposite it (2, 3). With weights w from the rest triangles,
//   b = sum_a w_a x_a,   E = 1/2 k |b|^2,   F_a = -k w_a b,   dF_a/dx_c = -k w_a w_c I,
// so the force is linear in positions and its Jacobian constant (what implicit steps like).
// The weights, in the rest plane with the edge of length L and heights h2, h3 of the opposite
// vertices over it: w2 = L / h2, w3 = L / h3, and the edge ends share -(w2 + w3) by where the
// feet of those heights fall, so b = L [(x2 - foot2) / h2 + (x3 - foot3) / h3]: L times the jump
// of the surface's slope across the edge (zero for any flat placement, and rotation invariant).
// b is |L| theta for a small fold theta at the edge. The stiffness: for bending rigidity B
// (N m), k = B / A with A the rest area of the two triangles, so that a fine mesh bent into a
// cylinder of curvature kappa stores B kappa^2 / 2 per area (docs/materials.md derives it;
// tested in HingeBending.*).
struct Hinge {
  std::array<int, 4> particle{};  // edge ends, then the two opposite vertices
  std::array<double, 4> weight{};  // dimensionless, sum zero
  double stiffness = 0.0;         // k, N/m
};

// The hinge of the edge (x0, x1) between triangles (x0, x1, x2) and (x1, x0, x3), rest
// positions given (flat: x2 and x3 on opposite sides of the edge in one plane, or folded, in
// which case the two triangles are unfolded about the edge), for bending rigidity B.
Hinge makeHinge(const std::array<int, 4>& particles, const Vec3& x0, const Vec3& x1,
                const Vec3& x2, const Vec3& x3, double rigidity);

// The hinges of every interior edge of a triangle list (an edge shared by exactly two
// triangles), in the order the edges first appear; rest positions x (3N).
std::vector<Hinge> meshHinges(const std::vector<Eigen::Vector3i>& triangles,
                              Eigen::Ref<const Vector> x, double rigidity);

// b = sum w_a x_a for positions x (3N).
Vec3 hingeVector(const Hinge& hinge, const double* x);
double hingeEnergy(const std::vector<Hinge>& hinges, Eigen::Ref<const Vector> x);

// The hinges around each particle, in CSR form, so a particle gathers its hinge forces in a
// fixed order (same bits at any thread count), as SpringAdjacency does for springs.
struct HingeAdjacency {
  std::vector<int> offsets;  // (N + 1)
  std::vector<int> hinge;    // (4H) the hinge
  std::vector<int> slot;     // (4H) which of its four particles this one is
  static HingeAdjacency build(int particle_count, const std::vector<Hinge>& hinges);
};

}  // namespace mysim
