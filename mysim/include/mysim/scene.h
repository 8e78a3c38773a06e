#pragma once
#include <expected>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <variant>

#include "mysim/blowup.h"
#include "mysim/chain_scene.h"
#include "mysim/circle_scene.h"
#include "mysim/cloth_scene.h"
#include "mysim/integrator.h"
#include "mysim/model.h"
#include "mysim/particles_scene.h"

namespace mysim {

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

// The kinds of system a scene can hold (scene_kind.h): a new kind is its header and source and
// one name here (and its source in mysim/CMakeLists.txt).
using SceneSystem = std::variant<CircleScene, ChainScene, ClothScene, ParticlesScene>;

// A scene as the user described it, validated: the plain description every engine is built from.
// No engine reads JSON. The schema is in docs/scenes.md.
struct Scene {
  std::string name;
  std::string description;
  std::string source;  // file it came from, for messages
  std::vector<std::string> needed_terms;  // `needs`: model terms it declares (model_terms.h)

  SceneSystem system = ClothScene{};  // "system": one kind and its own fields

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

// The scene file's system.type of the scene's kind ("cloth").
std::string_view systemType(const Scene& scene);

// What reading the scene skipped (a mesh file's unsupported lines): said, then the run goes on.
std::vector<std::string> sceneWarnings(const Scene& scene);

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
