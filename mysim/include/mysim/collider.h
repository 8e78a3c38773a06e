#pragma once
// The static colliders a model holds, any number of each. A collider is a plain struct with free
// functions (its file: mysim/<shape>_collider.h): signed distance, the contact point on its
// surface grown by its margin, its surface as quads to draw, and reading from / describing to
// JSON. Adding a shape: its file pair, one name in the variant below, and its Bullet twin
// (reference/src/static_collider.cpp); everything else (the viewer, the report, the model file)
// goes through this header.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <variant>
#include <vector>

#include "mysim/box_collider.h"
#include "mysim/plane_collider.h"
#include "mysim/sphere_collider.h"

namespace mysim {

using Collider = std::variant<Sphere, Plane, Box>;

inline const char* colliderType(const Collider& c) {
  return std::visit([](const auto& shape) { return shape.kType; }, c);
}
inline double colliderMargin(const Collider& c) {
  return std::visit([](const auto& shape) { return shape.margin; }, c);
}
inline const Friction& colliderFriction(const Collider& c) {
  return std::visit([](const auto& shape) -> const Friction& { return shape.friction; }, c);
}
inline double signedDistance(const Collider& c, const Vec3& x) {
  return std::visit([&](const auto& shape) { return signedDistance(shape, x); }, c);
}
inline std::optional<SurfacePoint> contactPoint(const Collider& c, const Vec3& x) {
  return std::visit([&](const auto& shape) { return contactPoint(shape, x); }, c);
}
inline SurfaceMesh surfaceMesh(const Collider& c, const SurfaceDrawing& drawing) {
  return std::visit([&](const auto& shape) { return surfaceMesh(shape, drawing); }, c);
}
// With a test for exits that lead into another collider and where the particle was as the step
// began (only a box has a choice of exits).
inline std::optional<SurfacePoint> contactPoint(const Collider& c, const Vec3& x,
                                                const Blocked& blocked, const Vec3& from) {
  if (const Box* box = std::get_if<Box>(&c)) return contactPoint(*box, x, blocked, from);
  return contactPoint(c, x);
}

// "sphere, plane, box": the types a scene may name.
std::string colliderTypes();
// One collider from a scene object whose "type" names its shape, with its "friction" (unknown
// keys refused).
Collider readCollider(FieldReader& r);
// "friction": {"static": MU_S, "kinetic": MU_K} of the object `r` reads, if it has one: each in
// [0, 100] (100 sticks on any slope up to 89.4 degrees), kinetic defaulting to static and never
// above it.
Friction readFriction(FieldReader& r);
// The shape's fields, and "friction" when it has any (frictionless colliders are described as
// before friction existed, so their model files and hashes did not change).
nlohmann::json describeCollider(const Collider& c);

}  // namespace mysim
