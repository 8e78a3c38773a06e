#include "mysim/box_collider.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <vector>

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
  return contactPoint(box, x, [](const Vec3&) { return false; }, x);
}

namespace {

// The face a particle now at `local` (inside) came in by from `from_local` (outside), as
// (axis, side): the slab it entered last along the straight path. -1 when it was inside already.
std::pair<int, double> entryFace(const Box& box, const Vec3& local, const Vec3& from_local) {
  int entry_axis = -1;
  double entry_side = 0.0, latest = -1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double side = from_local[axis] < 0.0 ? -1.0 : 1.0;
    const double outside = side * from_local[axis] - box.half_extents[axis];
    if (outside <= 0.0) continue;
    const double entered = outside / (side * (from_local[axis] - local[axis]));  // in (0, 1]
    if (entered > latest) {
      latest = entered;
      entry_axis = axis;
      entry_side = side;
    }
  }
  return {entry_axis, entry_side};
}

}  // namespace

std::optional<SurfacePoint> contactPoint(const Box& box, const Vec3& x, const Blocked& blocked,
                                         const Vec3& from) {
  const Vec3 local = x - box.center;
  const Vec3 q = local.cwiseAbs() - box.half_extents;  // > 0: outside along that axis
  if (q.maxCoeff() > 0.0) {
    // Outside: along the line from the nearest box point, if within the margin. (Inside, the
    // clamped point differs from x by round-off only: its direction would be noise.)
    const Vec3 nearest = box.center + local.cwiseMax(-box.half_extents).cwiseMin(box.half_extents);
    const Vec3 out = x - nearest;
    const double d = out.norm();
    if (d >= box.margin) return std::nullopt;
    return SurfacePoint{nearest + box.margin * (out / d), out / d};
  }
  // Inside or on a face: out through a face to margin beyond it, the face it came in by first,
  // then the nearest (on each axis the side the particle is on first; the earlier axis on a tie).
  struct Exit {
    bool way_in;
    double distance;
    SurfacePoint surface;
  };
  const auto [entry_axis, entry_side] = entryFace(box, local, from - box.center);
  std::vector<Exit> exits;
  for (int axis = 0; axis < 3; ++axis) {
    const double near_side = local[axis] < 0.0 ? -1.0 : 1.0;
    for (double side : {near_side, -near_side}) {
      Vec3 n = Vec3::Zero();
      n[axis] = side;
      Vec3 p = x;
      p[axis] = box.center[axis] + side * (box.half_extents[axis] + box.margin);
      const bool way_in = axis == entry_axis && side == entry_side;
      exits.push_back({way_in, box.half_extents[axis] - side * local[axis], {p, n}});
    }
  }
  std::stable_sort(exits.begin(), exits.end(), [](const Exit& a, const Exit& b) {
    return a.way_in != b.way_in ? a.way_in : a.distance < b.distance;
  });
  for (const Exit& e : exits) {
    if (!blocked(e.surface.point)) return e.surface;
  }
  return exits.front().surface;
}

SurfaceMesh surfaceMesh(const Box& box, const SurfaceDrawing& drawing) {
  const Vec3 half =
      box.half_extents.array() - std::min(drawing.inset, 0.5 * box.half_extents.minCoeff());
  SurfaceMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;  // e_u x e_w = e_axis
    for (double side : {-1.0, 1.0}) {
      const Vec3 n = side * Vec3::Unit(axis);
      std::array<Vec3, 4> corners;
      int k = 0;
      for (const auto& [a, b] : {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}}) {
        Vec3 p = box.center + half[axis] * n;
        p[u] += a * half[u];
        p[w] += b * half[w];
        corners[side > 0 ? k : 3 - k] = p;  // the far face turned round: outward either way
        ++k;
      }
      mesh.addQuad(corners, n);
    }
  }
  return mesh;
}

}  // namespace mysim
