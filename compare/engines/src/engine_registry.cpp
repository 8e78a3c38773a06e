#include "compare/engines/engine_registry.h"

#include "mysim/self_collision.h"
#include "compare/engines/work_count.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "compare/engines/external_engine.h"
#include "mysim/model_scales.h"
#include "mysim/run_limits.h"
#include "mysim/start_state.h"
#include "mysim/scene_file.h"
#include "reference/bullet_engine.h"

namespace springcheck {

// The registry's rows: one factory per engine kind, each in its own file (adding a built-in
// engine: that file and a line in the constructor below).
Engine mysimEngine();
Engine bulletEngine(reference::BulletEngine engine);
Engine externalEngine(const ExternalEngineSpec& spec);

RunConfig runConfig(const mysim::Scene& scene) {
  return {scene.source,     scene.name,
          scene.integrator, {scene.dt, scene.duration, scene.sample_interval},
          scene.limits,     scene.engine_settings};
}

EngineRegistry::EngineRegistry() {
  // The built-in rows.
  engines_.push_back(mysimEngine());
  for (reference::BulletEngine e : reference::kBulletEngines) engines_.push_back(bulletEngine(e));
  sections_.push_back(reference::bulletSceneSection());
}

std::expected<void, std::string> EngineRegistry::add(Engine engine) {
  if (find(engine.name)) return std::unexpected("engine '" + engine.name + "' exists already");
  engines_.push_back(std::move(engine));
  return {};
}

std::expected<void, std::string> EngineRegistry::addEnginesFile(const std::string& path) {
  auto specs = loadEnginesFile(path);
  if (!specs) return std::unexpected(specs.error());
  std::vector<Engine> added;
  for (std::size_t k = 0; k < specs->size(); ++k) {
    const ExternalEngineSpec& spec = (*specs)[k];
    if (find(spec.name)) {
      return std::unexpected(path + ": engines[" + std::to_string(k) + "].name: '" + spec.name +
                             "' is taken by another engine; choose another name");
    }
    added.push_back(externalEngine(spec));
  }
  for (Engine& e : added) engines_.push_back(std::move(e));
  engines_files_.push_back(path);
  return {};
}

std::vector<std::string> EngineRegistry::names() const {
  std::vector<std::string> names;
  for (const Engine& e : engines_) names.push_back(e.name);
  return names;
}

std::vector<std::string> EngineRegistry::specs(bool fixed_step_only) const {
  std::vector<std::string> specs;
  for (const Engine& e : engines_) {
    if (!e.takes_integrator) {
      specs.push_back(e.name);
      continue;
    }
    for (const std::string& integrator : mysim::integratorNames(fixed_step_only)) {
      specs.push_back(e.name + ":" + integrator);
    }
  }
  return specs;
}

std::vector<std::string> EngineRegistry::expand(const std::vector<std::string>& given) const {
  std::vector<std::string> out;
  for (const std::string& spec : given) {
    if (spec == "all" || spec == "all-fixed-step") {
      for (std::string& s : specs(spec != "all")) out.push_back(std::move(s));
    } else if (spec == "all-direct") {
      // The fixed-step engines but mysim's iterative families (passes to a tolerance), which a
      // study may map on their own (the main job's large-steps map).
      for (std::string& s : specs(true)) {
        const mysim::IntegratorInfo* info = mysim::findIntegrator(schemeOf(s, ""));
        if (info == nullptr || !mysim::iterativeFamily(info->family)) out.push_back(std::move(s));
      }
    } else {
      out.push_back(spec);
    }
  }
  return out;
}

std::string EngineRegistry::schemeOf(const std::string& spec,
                                     const std::string& scene_integrator) const {
  if (const auto colon = spec.find(':'); colon != std::string::npos) {
    const std::string integrator = spec.substr(colon + 1);  // "xpbd:substeps=10": the name
    return integrator.substr(0, integrator.find(':'));
  }
  const Engine* e = find(spec);
  if (!e) return "";
  return e->takes_integrator ? scene_integrator : e->scheme;
}

const Engine* EngineRegistry::find(const std::string& name) const {
  for (const Engine& e : engines_) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::expected<std::string, std::string> EngineRegistry::shippedScene(const std::string& name) const {
  namespace fs = std::filesystem;
  if (shipped_scenes_.empty()) return std::unexpected("no shipped scenes folder is known here");
  std::vector<std::string> found, names;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(shipped_scenes_, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file() || it->path().extension() != ".json") continue;
    names.push_back(it->path().stem().string());
    if (it->path().stem() == name) found.push_back(it->path().lexically_normal().string());
  }
  if (found.size() == 1) return found.front();
  std::sort(names.begin(), names.end());
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  if (found.empty()) {
    return std::unexpected("no shipped scene named '" + mysim::clip(name, 40) + "' in " +
                           shipped_scenes_ + " (shipped: " + list + ")");
  }
  return std::unexpected("'" + name + "' names " + std::to_string(found.size()) +
                         " shipped scenes; give the path");
}

std::expected<mysim::Scene, std::string> EngineRegistry::loadScene(const std::string& path) const {
  auto scene = mysim::loadScene(path, sections_);
  // What a mesh reader skipped is said, not dropped silently (the run goes on without it).
  if (scene) {
    for (const std::string& w : mysim::sceneWarnings(*scene)) std::cerr << "warning: " << w << '\n';
  }
  return scene;
}

std::string engineList(const EngineRegistry& registry) {
  std::string list;
  for (const Engine& e : registry.engines()) {
    list += (list.empty() ? "" : ", ") + e.name;
    if (e.takes_integrator) list += ", " + e.name + ":INTEGRATOR";
  }
  return list;
}

std::expected<std::pair<const Engine*, RunConfig>, EngineError> EngineRegistry::resolve(
    const std::string& spec, const RunConfig& config) const {
  auto unknown = [&](const std::string& why) {
    return std::unexpected(EngineError{EngineError::Kind::Unknown, why});
  };
  const std::size_t colon = spec.find(':');
  const Engine* engine = find(spec.substr(0, colon));
  if (!engine) {
    return unknown(
        "unknown engine '" + mysim::clip(spec, 40) + "'; expected one of " + engineList(*this) +
        (engines_files_.empty() ? " (a user's own engine comes from --engines-file)" : ""));
  }
  RunConfig resolved = config;
  if (colon != std::string::npos) {
    if (!engine->takes_integrator) {
      return unknown("engine '" + mysim::clip(spec, 40) + "': " + engine->name +
                     " takes no integrator");
    }
    // The sweeps' grammar: "mysim:xpbd:substeps=10:iterations=1" sets parameters too.
    auto variant = mysim::parseIntegratorVariant(spec.substr(colon + 1));
    if (!variant) return unknown("engine '" + mysim::clip(spec, 40) + "': " + variant.error());
    resolved.integrator.name = variant->name;
    for (const auto& [key, value] : variant->values) resolved.integrator.values[key] = value;
  }
  return std::pair{engine, std::move(resolved)};
}

namespace {

// The limits every run is held to, whatever set its step and duration.
std::optional<EngineError> limitError(const mysim::Model& model, const RunConfig& config) {
  const double particles = model.isCircle() ? 1 : model.particleCount();
  auto error = mysim::checkRunLimits(particles, model.springs.size(), config.run);
  if (!error) error = mysim::checkModelScales(model, config.run.dt);
  if (!error) error = mysim::checkStartOutsideColliders(model);
  if (!error) error = mysim::checkSelfCollision(model);
  if (!error) return std::nullopt;
  return EngineError{EngineError::Kind::Invalid,
                     config.source + ": " + error->field + ": " + error->message};
}

}  // namespace

std::expected<void, std::string> EngineRegistry::check(const std::string& spec) const {
  auto resolved = resolve(spec, RunConfig{});
  if (!resolved) return std::unexpected(resolved.error().message);
  return {};
}

std::expected<EngineInstance, EngineError> EngineRegistry::build(const std::string& spec,
                                                                 const mysim::Model& model,
                                                                 const RunConfig& config) const {
  auto resolved = resolve(spec, config);
  if (!resolved) return std::unexpected(resolved.error());
  if (auto limit = limitError(model, config)) return std::unexpected(*limit);
  return resolved->first->build(model, resolved->second);
}

void applyTiming(const Timing& timing, RunConfig& config) {
  config.repeats = timing.repeats;
  config.run.threads = timing.threads;
  config.run.follow_load = !timing.fixed_threads;
}

std::expected<mysim::RunRecord, EngineError> EngineRegistry::run(const std::string& spec,
                                                                 const mysim::Model& model,
                                                                 const RunConfig& config) const {
  auto resolved = resolve(spec, config);
  if (!resolved) return std::unexpected(resolved.error());
  if (auto limit = limitError(model, config)) return std::unexpected(*limit);
  const auto& [engine, resolved_config] = *resolved;
  auto once = [&]() -> std::expected<mysim::RunRecord, EngineError> {
    std::expected<mysim::RunRecord, EngineError> r = [&]() -> decltype(r) {
      if (engine->run) return engine->run(model, resolved_config);
      auto instance = engine->build(model, resolved_config);
      if (!instance) return std::unexpected(instance.error());
      mysim::RunRecord made = mysim::simulate(*instance->system, *instance->stepper,
                                              instance->start, resolved_config.run);
      made.integrator = instance->integrator;
      made.notes = instance->notes;
      return made;
    }();
    if (r) countRun(r->steps);  // a refusal stepped nothing
    return r;
  };
  auto record = once();
  if (!record) return record;
  record->engine = spec;
  // Repeats time the same run again; a run that differs from the first (it must not) fails.
  std::vector<double> walls{record->wall_seconds};
  for (int k = 1; k < config.repeats; ++k) {
    auto again = once();
    if (!again) return std::unexpected(again.error());
    if (again->steps != record->steps || again->frames.size() != record->frames.size() ||
        (!again->frames.empty() && again->frames.back() != record->frames.back())) {
      return std::unexpected(EngineError{
          EngineError::Kind::Failed,
          spec + ": repeat " + std::to_string(k + 1) +
              " of the run gave another result than the "
              "first: the engine is not deterministic, so its timing cannot be repeated"});
    }
    walls.push_back(again->wall_seconds);
    record->threads = std::max(record->threads, again->threads);
  }
  record->repeats = static_cast<int>(walls.size());
  const RepeatTimes times = repeatTimes(std::move(walls));
  record->wall_seconds = times.fastest;
  record->wall_median_seconds = times.median;
  return record;
}

RepeatTimes repeatTimes(std::vector<double> walls) {
  std::sort(walls.begin(), walls.end());
  const std::size_t half = walls.size() / 2;
  return {walls.front(), walls.size() % 2 ? walls[half] : 0.5 * (walls[half - 1] + walls[half])};
}

std::expected<mysim::RunRecord, EngineError> EngineRegistry::run(const std::string& spec,
                                                                 const mysim::Scene& scene) const {
  return run(spec, mysim::buildModel(scene), runConfig(scene));
}

}  // namespace springcheck
