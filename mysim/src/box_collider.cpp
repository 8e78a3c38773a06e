#include "mysim/box_collider.h"

#include <nlohmann/json.hpp>

#include "mysim/json_input.h"

namespace mysim {

Box Box::read(FieldReader& r) {
  Box b;
  b.center = r.vec3("center");
  b.half_extents = r.vec3("half_extents");
  if (!(b.half_extents.minCoeff() > 0.0)) {
    failField(r.field("half_extents"), "three positive half-lengths (m)", r.raw("half_extents"));
  }
  b.margin = r.nonNegative("margin", 1e-3 * b.half_extents.minCoeff());
  return b;
}

nlohmann::json Box::describe() const {
  return {{"type", kType},
          {"center", {center.x(), center.y(), center.z()}},
          {"half_extents", {half_extents.x(), half_extents.y(), half_extents.z()}},
          {"margin", margin}};
}

double signedDistance(const Box& box, const Vec3& x) {
  const Vec3 q = (x - box.center).cwiseAbs() - box.half_extents;  // > 0: outside along that axis
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

std::optional<SurfacePoint> contactPoint(const Box& box, const Vec3& x) {
  const Vec3 local = x - box.center;
  const Vec3 q = local.cwiseAbs() - box.half_extents;  // > 0: outside along that axis
  // The axis of the face nearest to a point inside or on the surface: where q is largest.
  int axis = 0;
  q.maxCoeff(&axis);
  const Vec3 nearest = box.center + local.cwiseMax(-box.half_extents).cwiseMin(box.half_extents);
  const Vec3 out = x - nearest;
  const double d = out.norm();  // 0 inside or on the surface
  if (d >= box.margin && q.maxCoeff() >= 0.0) return std::nullopt;
  if (d > 0.0) return SurfacePoint{nearest + box.margin * (out / d), out / d};
  // Inside or on a face: out through the face of least depth, to margin beyond it.
  Vec3 n = Vec3::Zero();
  n[axis] = local[axis] < 0.0 ? -1.0 : 1.0;
  Vec3 p = x;
  p[axis] = box.center[axis] + n[axis] * (box.half_extents[axis] + box.margin);
  return SurfacePoint{p, n};
}

}  // namespace mysim
