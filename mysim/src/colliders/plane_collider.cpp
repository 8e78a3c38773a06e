#include "mysim/plane_collider.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "mysim/json_input.h"

namespace mysim {

Plane Plane::read(FieldReader& r) {
  Plane p;
  p.point = r.vec3("point");
  p.normal = r.unitVec3("normal", Vec3::UnitY());
  p.margin = r.nonNegative("margin", p.margin);
  return p;
}

nlohmann::json Plane::describe() const {
  return {{"type", kType},
          {"point", {point.x(), point.y(), point.z()}},
          {"normal", {normal.x(), normal.y(), normal.z()}},
          {"margin", margin}};
}

double signedDistance(const Plane& plane, const Vec3& x) {
  return plane.normal.dot(x - plane.point);
}

std::optional<SurfacePoint> contactPoint(const Plane& plane, const Vec3& x) {
  const double d = signedDistance(plane, x);
  if (d >= plane.margin) return std::nullopt;
  return SurfacePoint{x + (plane.margin - d) * plane.normal, plane.normal};
}

SurfaceMesh surfaceMesh(const Plane& plane, const SurfaceDrawing& drawing) {
  const Vec3 middle = 0.5 * (drawing.low + drawing.high);
  const Vec3 foot = middle - plane.normal.dot(middle - plane.point) * plane.normal;
  const double half = std::max(0.25, 0.6 * (drawing.high - drawing.low).norm());
  const Vec3 u = plane.normal.unitOrthogonal(), w = plane.normal.cross(u);  // u x w = normal
  const int cells = 4;
  const auto corner = [&](int a, int b) {
    return Vec3(foot + half * ((2.0 * a / cells - 1) * u + (2.0 * b / cells - 1) * w));
  };
  SurfaceMesh mesh;
  for (int a = 0; a < cells; ++a) {
    for (int b = 0; b < cells; ++b) {
      mesh.addQuad({corner(a, b), corner(a + 1, b), corner(a + 1, b + 1), corner(a, b + 1)},
                   plane.normal);
    }
  }
  return mesh;
}

}  // namespace mysim
