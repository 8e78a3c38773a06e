#pragma once
#include <optional>

#include <nlohmann/json_fwd.hpp>

#include "mysim/collider_surface.h"

namespace mysim {

class FieldReader;

// A static infinite plane, solid on the side opposite its normal: the ground of a
// cloth-drop test ({"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]} in "colliders").
// Particles closer than margin to it, or behind it, are put at distance margin in front.
struct Plane {
  static constexpr const char* kType = "plane";
  Vec3 point = Vec3::Zero();     // m, any point of the plane
  Vec3 normal = Vec3::UnitY();   // unit, out of the solid side
  double margin = 1e-3;          // m
  Friction friction;  // none unless the scene gives "friction" (collider.h reads it)

  static Plane read(FieldReader& r);  // point, normal (normalised), margin (default 1 mm)
  nlohmann::json describe() const;
};

double signedDistance(const Plane& plane, const Vec3& x);
std::optional<SurfacePoint> contactPoint(const Plane& plane, const Vec3& x);

// Its drawing: a square of it under the drawing's box, centred below its middle and 1.2 times
// as wide as the box's diagonal (at least 0.5 m), in 4 x 4 quads; flat, so never inset.
SurfaceMesh surfaceMesh(const Plane& plane, const SurfaceDrawing& drawing);

}  // namespace mysim
