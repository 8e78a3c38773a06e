#include "compare/studies/ablation.h"

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "compare/metrics/settled_quantities.h"
#include "mysim/json_input.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

using nlohmann::json;

// The model terms the ablation knows: one row each, how to see it in a scene file and how to
// take it out. The only list of them.
struct ModelTerm {
  std::string name, description;
  std::function<bool(const json&)> present;
  std::function<void(json&)> remove;
};

bool positive(const json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_number() && j[key].get<double>() > 0.0;
}

const std::vector<ModelTerm>& modelTerms() {
  static const std::vector<ModelTerm> terms = {
      {"bending", "no bending energy: material.bending {\"model\": \"none\"} (a membrane)",
       [](const json& s) {
         const json& m = s["system"]["material"];
         return m.contains("bending") && m["bending"].value("model", "") != "none";
       },
       [](json& s) { s["system"]["material"]["bending"] = {{"model", "none"}}; }},
      {"damping", "material.damping_rate 0: no drag settles it",
       [](const json& s) { return positive(s["system"]["material"], "damping_rate"); },
       [](json& s) { s["system"]["material"].erase("damping_rate"); }},
      {"drag", "forces.drag 0",
       [](const json& s) { return s.contains("forces") && positive(s["forces"], "drag"); },
       [](json& s) { s["forces"].erase("drag"); }},
      {"wind", "no forces.wind",
       [](const json& s) { return s.contains("forces") && s["forces"].contains("wind"); },
       [](json& s) { s["forces"].erase("wind"); }},
      {"pin_motion", "pins held still: no forces.pin_motion",
       [](const json& s) { return s.contains("forces") && s["forces"].contains("pin_motion"); },
       [](json& s) { s["forces"].erase("pin_motion"); }},
      {"colliders", "no colliders (and no sphere)",
       [](const json& s) { return s.contains("colliders") || s.contains("sphere"); },
       [](json& s) { s.erase("colliders"), s.erase("sphere"); }},
  };
  return terms;
}

AblationRun runVariant(const EngineRegistry& registry, const std::string& path, json scene,
                       const TradeSetup& setup, const std::string& quantity, double reference,
                       double bound) {
  AblationRun run;
  scene["system"]["resolution"] = setup.resolution;
  auto parsed = mysim::parseScene(scene.dump(), path, registry.sceneSections());
  if (!parsed) {
    run.status = "refused: " + parsed.error();
    return run;
  }
  RunConfig config = runConfig(*parsed);
  config.run.dt = setup.dt;
  const mysim::Model model = mysim::buildModel(*parsed);
  const std::string engine = setup.integrator == "-" ? setup.engine : setup.engine + ":" + setup.integrator;
  auto record = registry.run(engine, model, config);
  if (!record) {
    run.status = "refused: " + record.error().message;
    return run;
  }
  run.status = record->status();
  run.wall_seconds = record->wall_seconds;
  const EngineMetrics metrics = engineMetrics(model, {engine, *record});
  const SettledQuantities q = settledQuantities(model, {engine, *record}, metrics);
  if (auto it = q.find(quantity); it != q.end()) {
    run.value = it->second.end;
    run.drift = it->second.drift();
    run.settled = run.status == "ok" && std::abs(*run.drift) <= kSettledFraction * bound;
    run.within = run.settled && std::abs(*run.value - reference) <= bound;
  }
  return run;
}

}  // namespace

std::expected<Ablation, std::string> ablate(const EngineRegistry& registry, const std::string& path,
                                            const TradeSetup& setup, const std::string& quantity,
                                            double reference, double bound) {
  auto scene = mysim::readJsonFile(path, "scene file");
  if (!scene) return std::unexpected(scene.error());
  Ablation a;
  a.full = runVariant(registry, path, *scene, setup, quantity, reference, bound);
  json droppable = *scene;
  std::vector<std::string> dropped;
  for (const ModelTerm& term : modelTerms()) {
    if (!term.present(*scene)) continue;
    json variant = *scene;
    term.remove(variant);
    AblationRun run = runVariant(registry, path, variant, setup, quantity, reference, bound);
    run.term = term.name;
    run.description = term.description;
    if (run.within) {
      term.remove(droppable);
      dropped.push_back(term.name);
    }
    a.without.push_back(run);
  }
  if (!dropped.empty()) {
    AblationRun together = runVariant(registry, path, droppable, setup, quantity, reference, bound);
    for (const std::string& d : dropped) together.term += (together.term.empty() ? "" : "+") + d;
    together.description = "every term that can go alone, taken out together";
    a.cheapest = together;
  }
  return a;
}

}  // namespace springcheck
