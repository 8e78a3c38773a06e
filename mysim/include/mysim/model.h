#pragma once
#include <optional>
#include <vector>

#include "mysim/pin_motion.h"
#include "mysim/sphere_collider.h"
#include "mysim/spring.h"
#include "mysim/types.h"
#include "mysim/wind.h"

namespace mysim {

// The regular grid a cloth was built from, kept for normals and mesh export.
// Particle index = row * cols + col.
struct GridShape {
  int rows = 0;
  int cols = 0;
};

// The built model: what does not change while stepping. Sizes in comments, N particles.
// Optional force terms are absent unless the scene names them, and then cost nothing.
struct Model {
  Vector mass;                  // (N) kg, > 0
  std::vector<char> pinned;     // (N) 1 = pinned: follows pin_motion from its start position
  Vector start_position;        // (3N) m
  Vector start_velocity;        // (3N) m/s
  std::vector<Spring> springs;  // flat list, any topology
  Vec3 gravity = Vec3::Zero();  // m/s^2
  double drag = 0.0;            // N s/m, viscous drag -drag * v on every particle
  std::optional<Wind> wind;
  std::optional<PinMotion> pin_motion;
  std::optional<Sphere> sphere;
  std::optional<GridShape> grid;

  int particleCount() const { return static_cast<int>(mass.size()); }
};

}  // namespace mysim
