#include "compare/engines.h"

#include "reference/bullet_engine.h"

namespace springcheck {

const std::vector<std::string>& engineNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"mysim"};
    for (const std::string& name : reference::bulletEngineNames()) all.push_back(name);
    return all;
  }();
  return names;
}

namespace {

std::expected<mysim::RunRecord, std::string> runMysim(const mysim::Scene& scene) {
  auto integrator = mysim::makeIntegrator(scene.integrator);
  if (!integrator)
    return std::unexpected(scene.source + ": integrator.name: " + integrator.error());
  std::unique_ptr<mysim::OdeSystem> system = mysim::makeSystem(scene);
  if ((*integrator)->needsParticles() && !system->particles()) {
    return std::unexpected(scene.source + ": integrator.name: '" + scene.integrator.name +
                           "' needs a particle system; the circle is a first-order ODE");
  }
  const mysim::State start = mysim::initialState(scene, *system);
  mysim::RunRecord record = mysim::simulate(*system, **integrator, start,
                                            {scene.dt, scene.duration, scene.sample_interval});
  record.engine = "mysim";
  record.integrator = scene.integrator.name;
  return record;
}

}  // namespace

std::expected<void, std::string> checkEngineName(const std::string& engine) {
  if (engine.rfind("mysim:", 0) == 0) {
    auto name = mysim::canonicalIntegratorName(engine.substr(6));
    if (!name) return std::unexpected("engine '" + engine + "': " + name.error());
    return {};
  }
  for (const std::string& name : engineNames()) {
    if (engine == name) return {};
  }
  std::string valid;
  for (const std::string& name : engineNames()) valid += (valid.empty() ? "" : ", ") + name;
  return std::unexpected("unknown engine '" + engine + "'; expected one of " + valid +
                         " (or mysim:INTEGRATOR)");
}

std::expected<mysim::RunRecord, std::string> runEngine(const mysim::Scene& scene,
                                                       const std::string& engine) {
  if (auto known = checkEngineName(engine); !known) return std::unexpected(known.error());
  if (engine == "mysim") return runMysim(scene);
  // "mysim:INTEGRATOR" runs the scene with another integrator.
  if (engine.rfind("mysim:", 0) == 0) {
    mysim::Scene with_integrator = scene;
    with_integrator.integrator.name = *mysim::canonicalIntegratorName(engine.substr(6));
    auto record = runMysim(with_integrator);
    if (record) record->engine = engine;
    return record;
  }
  return reference::runBullet(scene, *reference::bulletEngineNamed(engine));
}

}  // namespace springcheck
