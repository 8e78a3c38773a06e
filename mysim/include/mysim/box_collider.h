#pragma once
#include <nlohmann/json_fwd.hpp>
#include <optional>

#include "mysim/collider_surface.h"

namespace mysim {

class FieldReader;

// A static box, axis-aligned ({"type": "box", "center": [...], "half_extents":
// [...]} in "colliders"). A particle inside goes out through the nearest face; one outside but
// closer than margin goes to distance margin along the line from its nearest box point (so the
// grown surface has rounded edges and corners, as Bullet's margins do).
struct Box {
  static constexpr const char* kType = "box";
  Vec3 center = Vec3::Zero();             // m
  Vec3 half_extents = Vec3::Constant(1);  // m, each > 0
  double margin = 0.0;                    // m
  Friction friction;  // none unless the scene gives "friction" (collider.h reads it)

  static Box read(FieldReader& r);  // center, half_extents, margin (default 1e-3 smallest half)
  nlohmann::json describe() const;
};

// Exact signed distance to the box surface (negative inside: minus the depth below the nearest
// face).
double signedDistance(const Box& box, const Vec3& x);
std::optional<SurfacePoint> contactPoint(const Box& box, const Vec3& x);
// The same, a particle inside leaving through the nearest face whose exit is not `blocked` (the
// nearest of all if every one is).
std::optional<SurfacePoint> contactPoint(const Box& box, const Vec3& x, const Blocked& blocked);

// Its drawing: its six faces, each half extent less the inset.
SurfaceMesh surfaceMesh(const Box& box, const SurfaceDrawing& drawing);

}  // namespace mysim
