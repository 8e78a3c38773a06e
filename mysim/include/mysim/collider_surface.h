#pragma once
// What a collider shape answers about a point near it, and the friction it carries: the types each
// shape's file and the contact (mysim/contact.h) share.
#include <array>
#include <functional>
#include <vector>

#include "mysim/types.h"

namespace mysim {

// Where a particle must go when it touches a static collider: the nearest point of the collider's
// surface grown by its margin, and the outward normal there.
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;  // unit
};

// Whether a point lies inside another collider: a shape with several ways out (a box's faces)
// takes the nearest one that does not lead into another collider (a box standing on the ground
// must not push a node out through its bottom face, into the ground).
using Blocked = std::function<bool(const Vec3&)>;

// A collider's Coulomb friction ("friction": {"static": MU_S, "kinetic": MU_K} in a scene; both
// 0, frictionless, when absent): mu_s >= mu_k >= 0.
struct Friction {
  double static_coefficient = 0.0;
  double kinetic = 0.0;
  bool any() const { return static_coefficient > 0.0 || kinetic > 0.0; }
};

// A collider's surface as flat quads, for drawing it (the viewer's shaded view, the report's
// wire frames and outlines): a sphere's quads run along its parallels and meridians, a box's are
// its faces. Each corner has its outward normal (a curved shape shades smoothly).
struct SurfaceMesh {
  std::vector<Vec3> points;
  std::vector<Vec3> normals;             // one per point, unit, outward
  std::vector<std::array<int, 4>> quads;  // counter-clockwise seen from outside
  void addQuad(const std::array<Vec3, 4>& corners, const Vec3& normal) {
    const int first = static_cast<int>(points.size());
    for (const Vec3& p : corners) {
      points.push_back(p);
      normals.push_back(normal);
    }
    quads.push_back({first, first + 1, first + 2, first + 3});
  }
};

// What a drawing is for: the box around what is drawn with the collider (a cloth), which an
// endless shape (a plane) is drawn under, and how far inside its true surface to draw it (flat
// triangles between nodes resting on a curved or edged surface cut into it; drawn at its true
// size it would show through the cloth where no node is inside: docs/viewer.md). A shape is
// never drawn smaller than half its size.
struct SurfaceDrawing {
  Vec3 low = Vec3::Zero();
  Vec3 high = Vec3::Zero();
  double inset = 0.0;  // m
};
// A drawing around points (3 x N; none: around the origin), `inset` inside the true surface.
inline SurfaceDrawing drawingAround(const Eigen::Ref<const Eigen::Matrix3Xd>& points, double inset) {
  if (points.cols() == 0) return {Vec3::Zero(), Vec3::Zero(), inset};
  return {points.rowwise().minCoeff(), points.rowwise().maxCoeff(), inset};
}

}  // namespace mysim
