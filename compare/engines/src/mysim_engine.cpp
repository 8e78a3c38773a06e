// mysim: our simulator, stepped by the integrator the run names ("mysim:verlet" picks one).
#include "compare/engines/engine_registry.h"
#include "compare/engines/external_engine.h"
#include "reference/bullet_engine.h"

namespace springcheck {

Engine mysimEngine() {
  Engine e;
  e.name = "mysim";
  e.kind = "mysim";
  e.description = "springcheck's own simulator; mysim:INTEGRATOR picks the integrator";
  e.takes_integrator = true;
  e.build = [](const mysim::Model& model,
               const RunConfig& config) -> std::expected<EngineInstance, EngineError> {
    const mysim::IntegratorInfo* info = mysim::findIntegrator(config.integrator.name);
    if (!info) {
      return std::unexpected(
          EngineError{EngineError::Kind::Unknown,
                      config.source + ": integrator.name: " +
                          mysim::canonicalIntegratorName(config.integrator.name).error()});
    }
    if (auto refusal = mysim::circleRefusal(info->name); refusal && model.isCircle()) {
      return std::unexpected(EngineError{
          EngineError::Kind::Refused, config.source + ": mysim: integrator.name: " + *refusal});
    }
    EngineInstance instance;
    instance.system = mysim::makeSystem(mysim::borrowed(model), config.limits);
    instance.stepper =
        std::make_unique<mysim::IntegratorStepper>(*instance.system, info->make(config.integrator));
    instance.start = instance.system->initialState();
    instance.integrator = info->name;
    return instance;
  };
  return e;
}

}  // namespace springcheck
