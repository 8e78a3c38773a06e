#include "compare/studies/ablation.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "compare/metrics/settled_quantities.h"
#include "mysim/json_input.h"
#include "mysim/model_terms.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

using nlohmann::json;

}  // namespace

bool sceneDeclares(const json& scene, const std::string& term) {
  if (!scene.contains("needs") || !scene["needs"].is_array()) return false;
  const json& needs = scene["needs"];
  return std::find(needs.begin(), needs.end(), json(term)) != needs.end();
}

namespace {

AblationRun runVariant(const EngineRegistry& registry, const std::string& path, json scene,
                       const TradeSetup& setup, const std::string& quantity, double reference,
                       double bound) {
  AblationRun run;
  scene["system"]["resolution"] = setup.resolution;
  scene.erase("needs");  // the variant may lack a term the scene declares
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
  for (const mysim::ModelTerm& term : mysim::modelTerms()) {
    if (!term.present(*scene)) continue;
    json variant = *scene;
    term.remove(variant);
    AblationRun run = runVariant(registry, path, variant, setup, quantity, reference, bound);
    run.term = term.name;
    run.description = term.description;
    run.declared = sceneDeclares(*scene, term.name);
    if (run.within && !run.declared) {
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
