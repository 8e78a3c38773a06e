// The Bullet twins (reference/): each steps a Bullet world built from the model.
#include "reference/bullet_engine.h"

#include "compare/engines/engine_registry.h"
#include "compare/engines/external_engine.h"

namespace springcheck {

Engine bulletEngine(reference::BulletEngine which) {
  Engine e;
  e.name = reference::bulletEngineName(which);
  e.kind = "bullet";
  e.description = reference::bulletEngineDescription(which);
  e.scheme = reference::bulletScheme(which);
  e.build = [which](const mysim::Model& model,
                    const RunConfig& config) -> std::expected<EngineInstance, EngineError> {
    const reference::BulletSettings settings = reference::bulletSettings(
        config.source, config.run.dt, config.integrator, config.engine_settings);
    auto stepper = reference::makeBulletStepper(model, which, settings);
    if (!stepper) return std::unexpected(EngineError{EngineError::Kind::Refused, stepper.error()});
    EngineInstance instance;
    instance.notes = (*stepper)->notes();
    instance.stepper = std::move(*stepper);
    // mysim's system of the same model: start state, health checks, energy, output rows.
    instance.system = mysim::makeSystem(mysim::borrowed(model), config.limits);
    instance.start = instance.system->initialState();
    instance.integrator = reference::bulletIntegratorName(which, settings.classic_iterations);
    return instance;
  };
  return e;
}

}  // namespace springcheck
