#include "compare/studies/capstan_study.h"

namespace springcheck {

std::expected<bool, std::string> CapstanTrials::holds(const EngineRegistry& registry,
                                                      const std::string& engine, double load) const {
  mysim::Model loaded = model;
  loaded.mass[capstan.load] = load;
  auto run = registry.run(engine, loaded, config);
  if (!run) return std::unexpected(run.error().message);
  if (run->blowup) {
    return std::unexpected("the run blew up at t = " + std::to_string(run->blowup->time) + " s with a load of " +
                           std::to_string(load) + " kg");
  }
  return loadDriftOverLastHalf(capstan, *run) < kHeld;
}

std::expected<CapstanTrials, std::string> capstanTrials(const mysim::Scene& scene) {
  mysim::Model model = mysim::buildModel(scene);
  mysim::ParticleRows first(model.particleCount(), 6);
  for (int p = 0; p < model.particleCount(); ++p) {
    first.row(p).head<3>() = mysim::at3(model.start_position, p).transpose();
    first.row(p).tail<3>() = mysim::at3(model.start_velocity, p).transpose();
  }
  const std::optional<Capstan> capstan = capstanOf(model, first);
  if (!capstan) {
    return std::unexpected(scene.source + ": not a capstan (docs/contact.md: a chain of springs over one sphere "
                           "with friction, a mass at each end ten times any other particle's, no pins)");
  }
  const double predicted = capstan->holdingLoad(model);
  return CapstanTrials{scene.name, std::move(model), *capstan, runConfig(scene), predicted};
}

std::expected<CapstanMeasurement, std::string> measureCapstan(const EngineRegistry& registry,
                                                              const std::string& engine,
                                                              const mysim::Scene& scene) {
  auto trials = capstanTrials(scene);
  if (!trials) return std::unexpected(trials.error());
  CapstanMeasurement m{scene.name, engine, trials->capstan, trials->model.mass[trials->capstan.hold],
                       trials->predicted_load};
  double low = m.hold_mass, high = 2.0 * m.predicted_load;
  for (double bound : {low, high}) {
    auto held = trials->holds(registry, engine, bound);
    ++m.runs;
    if (!held) return std::unexpected(held.error());
    if (*held != (bound == low)) {
      return std::unexpected(engine + (bound == low ? ": slips with equal masses at its ends"
                                                   : ": holds even twice the closed form's load"));
    }
  }
  for (int k = 0; k < kBisections; ++k) {
    const double middle = 0.5 * (low + high);
    auto held = trials->holds(registry, engine, middle);
    ++m.runs;
    if (!held) return std::unexpected(held.error());
    (*held ? low : high) = middle;
  }
  m.measured_load = low;
  m.slipped_load = high;
  return m;
}

}  // namespace springcheck
