#include "mysim/plane_collider.h"

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

}  // namespace mysim
