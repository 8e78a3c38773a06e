#include "mysim/scene.h"

#include "mysim/circle_system.h"
#include "mysim/particle_system.h"

namespace mysim {

namespace {

// Every alternative of the variant is a whole scene kind (scene_kind.h).
template <class... Kinds>
constexpr bool everyOneIsASceneKind(const std::variant<Kinds...>*) {
  return (SceneKind<Kinds> && ...);
}
static_assert(everyOneIsASceneKind(static_cast<const SceneSystem*>(nullptr)));

}  // namespace

std::string_view systemType(const Scene& scene) {
  return std::visit([](const auto& kind) -> std::string_view { return kind.kType; }, scene.system);
}

std::vector<std::string> sceneWarnings(const Scene& scene) {
  return std::visit([](const auto& kind) { return kind.warnings(); }, scene.system);
}

Model buildModel(const Scene& scene) {
  Model model;
  std::visit([&](const auto& kind) { kind.build(model); }, scene.system);
  model.gravity = scene.gravity;
  model.drag = scene.drag;
  model.wind = scene.wind;
  model.pin_motion = scene.pin_motion;
  model.colliders = scene.colliders;
  model.self_collision_thickness = scene.self_collision_thickness;
  return model;
}

std::unique_ptr<OdeSystem> makeSystem(std::shared_ptr<const Model> model,
                                      const BlowUpLimits& limits) {
  if (model->isCircle()) return std::make_unique<CircleSystem>(*model->circle_start);
  return std::make_unique<ParticleSystem>(std::move(model), limits);
}

}  // namespace mysim
