#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <vector>

#include "compare/metrics/drape_metric.h"

namespace springcheck {

// A surface to measure against: vertices and triangles. A chain is a polyline, given as
// degenerate triangles (a, b, b); a lone point as (a, a, a).
struct Surface {
  Positions vertices;
  std::vector<Eigen::Vector3i> triangles;
};

// Distance from a point to a triangle (closest point on the closed triangle, degenerate ones
// included), after Ericson, Real-Time Collision Detection, 5.1.5.
double pointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                             const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Topology-free distances between two surfaces, over the vertices of each to the other surface:
//   chamfer   = (mean_a d(a, B) + mean_b d(b, A)) / 2
//   hausdorff = max(max_a d(a, B), max_b d(b, A))
// so a 16 x 16 cloth can be held against a 64 x 64 one. Brute force: O(Va Tb + Vb Ta).
struct SurfaceDistance {
  double chamfer = 0.0;
  double hausdorff = 0.0;
};
SurfaceDistance surfaceDistance(const Surface& a, const Surface& b);

}  // namespace springcheck
