#include "mysim/sphere_collider.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "mysim/json_input.h"

namespace mysim {

Sphere Sphere::read(FieldReader& r) {
  Sphere s;
  s.center = r.vec3("center");
  s.radius = r.positive("radius");
  s.margin = r.nonNegative("margin", 1e-3 * s.radius);
  return s;
}

nlohmann::json Sphere::describe() const {
  return {{"type", kType},
          {"center", {center.x(), center.y(), center.z()}},
          {"radius", radius},
          {"margin", margin}};
}

double signedDistance(const Sphere& sphere, const Vec3& x) {
  return (x - sphere.center).norm() - sphere.radius;
}

std::optional<SurfacePoint> contactPoint(const Sphere& sphere, const Vec3& x) {
  const double surface = sphere.radius + sphere.margin;
  const Vec3 d = x - sphere.center;
  const double r2 = d.squaredNorm();
  if (r2 >= surface * surface) return std::nullopt;
  const double r = std::sqrt(r2);
  // A particle exactly at the centre has no outward direction: push it up (+y).
  const Vec3 n = r > 0.0 ? Vec3(d / r) : Vec3::UnitY();
  return SurfacePoint{sphere.center + surface * n, n};
}

SurfaceMesh surfaceMesh(const Sphere& sphere, const SurfaceDrawing& drawing) {
  const double radius = std::max(0.5 * sphere.radius, sphere.radius - drawing.inset);
  const int stacks = 16, slices = 32;
  SurfaceMesh mesh;
  for (int i = 0; i <= stacks; ++i) {
    const double polar = M_PI * i / stacks;  // from +y
    for (int j = 0; j <= slices; ++j) {
      const double around = 2 * M_PI * j / slices;
      const Vec3 n(std::sin(polar) * std::cos(around), std::cos(polar),
                   std::sin(polar) * std::sin(around));
      mesh.points.push_back(sphere.center + radius * n);
      mesh.normals.push_back(n);
    }
  }
  const auto at = [&](int i, int j) { return i * (slices + 1) + j; };
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) mesh.quads.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
  }
  return mesh;
}

}  // namespace mysim
