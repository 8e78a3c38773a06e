#pragma once
#include <expected>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mysim/blowup.h"
#include "mysim/chain.h"
#include "mysim/cloth.h"
#include "mysim/cloth_material.h"
#include "mysim/integrator.h"
#include "mysim/model.h"
#include "mysim/triangle_mesh.h"

namespace mysim {

struct ExplicitParticle {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  double mass = 1.0;
  bool pinned = false;
};

// Settings a scene may carry for an engine outside mysim, in a top-level section of the engine's
// own ("bullet": {"classic_iterations": 10}). The engine declares the section; the scene reader
// checks its numbers against the declaration (range, integer, unknown keys) like any other field
// and keeps them, defaults filled in, for the engine. mysim never interprets them.
struct EngineSetting {
  std::string key;
  double low = 0.0, high = 0.0;  // accepted range, inclusive
  double fallback = 0.0;         // when the scene does not set it
  bool integer = false;
  std::string meaning;
};
struct EngineSection {
  std::string name;
  std::vector<EngineSetting> settings;
};
// section -> key -> value, for every declared section (defaults where the scene is silent).
using EngineSettings = std::map<std::string, std::map<std::string, double>>;

// A scene as the user described it, validated: the plain description every engine is built from.
// No engine reads JSON. The schema is in docs/scenes.md.
struct Scene {
  std::string name;
  std::string description;
  std::string source;  // file it came from, for messages
  std::vector<std::string> needed_terms;  // `needs`: model terms it declares (model_terms.h)

  SystemKind kind = SystemKind::Cloth;
  Eigen::Vector2d circle_start{1.0, 0.0};
  ChainShape chain;
  ClothShape cloth;
  std::optional<ClothMaterial> cloth_material;  // cloth from its material (docs/materials.md)
  MaterialGrid material_grid;                   // its grid, when cloth_material is set
  bool material_clamped = false;                // pins "left_clamp"
  std::optional<TriangleMesh> cloth_mesh;       // a mesh cloth (with cloth_material)
  double mesh_drag = 0.0;                       // N s/m its damping rate means
  double chain_end_mass = 0.0;                  // a material chain's end particles (half a link), kg
  double material_drag = 0.0;                   // N s/m a material chain's damping rate means
  std::vector<ExplicitParticle> particles;  // kind == Particles
  std::vector<Spring> springs;              // kind == Particles
  std::vector<int> pins;                    // chain and cloth: pinned particle indices
  Vec3 start_velocity = Vec3::Zero();       // chain and cloth: every particle's initial velocity

  Vec3 gravity = Vec3::Zero();
  double drag = 0.0;
  std::optional<Wind> wind;
  std::optional<PinMotion> pin_motion;
  std::vector<Collider> colliders;  // "sphere" (first, if given), then "colliders"
  std::optional<double> self_collision_thickness;  // system.self_collision.thickness, m

  IntegratorSettings integrator;
  double dt = 0.04;              // s
  double duration = 10.0;        // s
  double sample_interval = 0.0;  // s between trajectory frames; 0 = about 200 frames a run
  BlowUpLimits limits;
  EngineSettings engine_settings;
};

// The model of a scene: every particle, spring and force term, expanded.
Model buildModel(const Scene& scene);

// The system of a model: the circle's ODE or particles under the model's forces, which share the
// model (ParticleSystem): a copy of a Model passed by value, or borrowed(model) without one.
std::unique_ptr<OdeSystem> makeSystem(std::shared_ptr<const Model> model,
                                      const BlowUpLimits& limits);
inline std::unique_ptr<OdeSystem> makeSystem(Model model, const BlowUpLimits& limits) {
  return makeSystem(std::make_shared<const Model>(std::move(model)), limits);
}
inline std::unique_ptr<OdeSystem> makeSystem(const Scene& scene) {
  return makeSystem(buildModel(scene), scene.limits);
}

}  // namespace mysim
