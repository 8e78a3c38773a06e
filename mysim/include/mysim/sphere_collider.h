#pragma once
#include <optional>

#include <nlohmann/json_fwd.hpp>

#include "mysim/collider_surface.h"

namespace mysim {

class FieldReader;

// A static sphere (scene: "sphere": {...} or {"type": "sphere", ...} in
// "colliders"). Particles closer to its centre than radius + margin are put on that surface.
struct Sphere {
  static constexpr const char* kType = "sphere";
  Vec3 center = Vec3::Zero();
  double radius = 1.0;  // m
  double margin = 0.0;  // m, the surface particles are put back on is radius + margin
  Friction friction;  // none unless the scene gives "friction" (collider.h reads it)

  static Sphere read(FieldReader& r);  // center, radius, margin (default 1e-3 radius)
  nlohmann::json describe() const;     // the same fields, for model files
};

// Distance from x to the sphere's surface, negative inside (m).
double signedDistance(const Sphere& sphere, const Vec3& x);
// The point of radius + margin nearest to x, when x is inside it.
std::optional<SurfacePoint> contactPoint(const Sphere& sphere, const Vec3& x);

// Its drawing: parallels and meridians on the radius less the inset.
SurfaceMesh surfaceMesh(const Sphere& sphere, const SurfaceDrawing& drawing);

}  // namespace mysim
