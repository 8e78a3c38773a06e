#include "engine_support.h"
#include "reference/bullet_engine.h"
#include "steppers.h"

namespace reference {

std::expected<std::unique_ptr<BulletStepper>, std::string> makeBulletStepper(
    const mysim::Scene& scene, const mysim::Model& model, BulletEngine engine) {
  if (auto supported = checkSupported(scene, model, engine); !supported) {
    return std::unexpected(supported.error());
  }
  if (engine == BulletEngine::Classic) return makeClassicStepper(scene, model);
  return makeDeformableStepper(scene, model, engine == BulletEngine::Implicit);
}

std::expected<mysim::RunRecord, std::string> runBullet(const mysim::Scene& scene,
                                                       BulletEngine engine) {
  if (scene.kind == mysim::SystemKind::Circle) {
    return std::unexpected(scene.source + ": " + bulletEngineName(engine) +
                           ": system.type: the circle is a first-order ODE, not a soft body");
  }
  // The mysim system of the same model gives the start state, the health checks and the energy,
  // so every engine is judged by the same code.
  mysim::ParticleSystem system(mysim::buildModel(scene), scene.limits);
  auto stepper = makeBulletStepper(scene, system.model(), engine);
  if (!stepper) return std::unexpected(stepper.error());
  mysim::RunRecord record = mysim::simulate(system, **stepper, system.initialState(),
                                            {scene.dt, scene.duration, scene.sample_interval});
  record.engine = bulletEngineName(engine);
  switch (engine) {
    case BulletEngine::Deformable:
      record.integrator = "bullet-explicit";
      break;
    case BulletEngine::Implicit:
      record.integrator = "bullet-backward-euler";
      break;
    case BulletEngine::Classic:
      record.integrator = "bullet-pbd-" + std::to_string(scene.classic.iterations);
      break;
  }
  record.notes = (*stepper)->notes();
  return record;
}

}  // namespace reference
