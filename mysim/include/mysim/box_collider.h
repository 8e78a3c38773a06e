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
// The same, a particle inside leaving through the face it came in by, when `from` (where it was
// as the step began) is outside, else through the nearest face; either way only through a face
// whose exit is not `blocked` (the nearest if every one is). Why the way in: a step may carry a
// particle deeper into a thin box than its half thickness, and the nearest face is then the far
// one (a cloth at 1/60 s fell off the top of the 2 cm wall of cloth_over_thin_wall through its
// sides).
std::optional<SurfacePoint> contactPoint(const Box& box, const Vec3& x, const Blocked& blocked,
                                         const Vec3& from);

// Its drawing: its six faces, each half extent less the inset.
SurfaceMesh surfaceMesh(const Box& box, const SurfaceDrawing& drawing);

}  // namespace mysim
