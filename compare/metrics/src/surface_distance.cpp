#include "compare/metrics/surface_distance.h"

#include <algorithm>
#include <limits>

namespace springcheck {

using Eigen::Vector3d;

namespace {

// Closest point on segment ab to p.
Vector3d closestOnSegment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return a;
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return a + t * ab;
}

}  // namespace

double pointTriangleDistance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  // Degenerate (a segment or a point): the nearest of its edges.
  if (n2 < 1e-30) {
    return std::min({(p - closestOnSegment(p, a, b)).norm(), (p - closestOnSegment(p, b, c)).norm(),
                     (p - closestOnSegment(p, a, c)).norm()});
  }
  // Project onto the plane; inside the triangle (all barycentrics >= 0) the distance is to the
  // plane, else to the nearest edge.
  const Vector3d q = p - n * ((p - a).dot(n) / n2);
  const bool inside = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
                      (a - c).cross(q - c).dot(n) >= 0;
  if (inside) return (p - q).norm();
  return std::min({(p - closestOnSegment(p, a, b)).norm(), (p - closestOnSegment(p, b, c)).norm(),
                   (p - closestOnSegment(p, c, a)).norm()});
}

namespace {

// Mean and max over the vertices of `from` of their distance to the surface `to`.
std::pair<double, double> oneSided(const Surface& from, const Surface& to) {
  double sum = 0.0, worst = 0.0;
  for (int i = 0; i < from.vertices.rows(); ++i) {
    const Vector3d p = from.vertices.row(i).transpose();
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3i& t : to.triangles) {
      nearest = std::min(nearest, pointTriangleDistance(p, to.vertices.row(t[0]).transpose(),
                                                        to.vertices.row(t[1]).transpose(),
                                                        to.vertices.row(t[2]).transpose()));
    }
    sum += nearest;
    worst = std::max(worst, nearest);
  }
  return {from.vertices.rows() ? sum / from.vertices.rows() : 0.0, worst};
}

}  // namespace

SurfaceDistance surfaceDistance(const Surface& a, const Surface& b) {
  const auto [mean_ab, max_ab] = oneSided(a, b);
  const auto [mean_ba, max_ba] = oneSided(b, a);
  return {0.5 * (mean_ab + mean_ba), std::max(max_ab, max_ba)};
}

}  // namespace springcheck
