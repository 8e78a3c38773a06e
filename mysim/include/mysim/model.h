#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mysim/pin_motion.h"
#include "mysim/collider.h"
#include "mysim/hinge.h"
#include "mysim/material.h"
#include "mysim/spring.h"
#include "mysim/spring_list.h"
#include "mysim/types.h"
#include "mysim/wind.h"

namespace mysim {

// The regular grid a cloth was built from, kept for normals and mesh export.
// Particle index = row * cols + col.
struct GridShape {
  int rows = 0;
  int cols = 0;
};

// How messages name the scene fields a model's masses and springs came from: each particle and
// spring its own entry ("system.particles[3].mass", "system.springs[4].stiffness"), one value
// for all ("system.particle_mass", "system.stiffness"), or one per spring family
// ("system.shear.stiffness"). A scene kind's builder says which (scene_kind.h).
enum class FieldNaming { PerItem, Shared, PerFamily };

// The built model: what does not change while stepping, and the contract every engine, sweep and
// stability study takes (they scale the model, never the parsed scene). Sizes in comments, N
// particles. Optional force terms are absent unless the scene names them, and then cost nothing.
struct Model {
  std::string kind = "particles";  // the scene's system type it was built from (output names it)
  FieldNaming naming = FieldNaming::PerItem;  // how messages name its fields
  bool hangs_from_pins = false;  // a body built to hang from its pins (a chain, a cloth)
  // Set for the seed's first-order ODE x' = -y, y' = x only: its start point (N = 0).
  std::optional<Eigen::Vector2d> circle_start;

  Vector mass;                  // (N) kg, > 0
  std::vector<char> pinned;     // (N) 1 = pinned: follows pin_motion from its start position
  Vector start_position;        // (3N) m
  Vector start_velocity;        // (3N) m/s
  SpringList springs;           // flat list, any topology; shared by copies of the model
  std::vector<Hinge> hinges;    // bending across mesh edges (hinge.h); empty unless a scene asks
  Vec3 gravity = Vec3::Zero();  // m/s^2
  double drag = 0.0;            // N s/m, viscous drag -drag * v on every particle
  std::optional<Wind> wind;
  std::optional<PinMotion> pin_motion;
  std::vector<Collider> colliders;  // static, each with its friction; contacts in this order
  std::optional<GridShape> grid;
  std::vector<Eigen::Vector3i> mesh_triangles;  // a mesh cloth's triangles (a grid's: gridTriangles)
  std::optional<MaterialSource> material;  // set when the scene described a material
  // Self-collision's thickness, m (self_collision.h); absent: the mesh may pass through itself.
  std::optional<double> self_collision_thickness;

  int particleCount() const { return static_cast<int>(mass.size()); }
  bool isCircle() const { return circle_start.has_value(); }
  bool hangsFromPins() const { return hangs_from_pins; }
  // A cloth with triangles (its grid's or its mesh's): a surface to draw, export or collide.
  bool hasSurface() const { return grid.has_value() || !mesh_triangles.empty(); }
};

// The scene field a spring's parameter came from, for messages (FieldNaming): "system.stiffness"
// (chain), "system.shear.damping" (cloth), "system.springs[4].stiffness" (explicit particles).
std::string springField(const Model& model, int spring, const std::string& parameter);

// Where a pinned particle must be at time t (its start position moved by the pin motion), and
// the velocity every pinned particle has then.
Vec3 pinnedPosition(const Model& model, int particle, double t);
Vec3 pinnedVelocity(const Model& model, double t);

// Every spring's and hinge's stiffness times `scale` (sweeps and stability studies scale the
// model).
void scaleStiffness(Model& model, double scale);

// A model lent to a system without a copy (makeSystem, ParticleSystem): a shared pointer that
// owns nothing, for a caller that keeps `model` alive and unchanged for as long as the system
// lives (an engine's instance and the model its registry was given).
inline std::shared_ptr<const Model> borrowed(const Model& model) {
  return std::shared_ptr<const Model>(std::shared_ptr<const Model>(), &model);
}

}  // namespace mysim
