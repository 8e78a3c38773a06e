#include "compare/studies/gate_ablation.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "compare/io/text_format.h"
#include "compare/studies/ablation.h"
#include "mysim/model_terms.h"
#include "mysim/scene_file.h"

namespace springcheck {
namespace {

using nlohmann::json;

// The checks of one scene key, with the gate's results for them, in the file's order.
struct SceneChecks {
  std::vector<const CheckResult*> results;
  std::vector<std::string> engines;
};

std::vector<std::pair<std::string, SceneChecks>> byScene(const GateReport& report) {
  std::vector<std::pair<std::string, SceneChecks>> scenes;
  for (const CheckResult& r : report.results) {
    const std::string key = r.check.sceneKey();
    auto at = std::find_if(scenes.begin(), scenes.end(), [&](auto& s) { return s.first == key; });
    if (at == scenes.end()) at = scenes.insert(scenes.end(), {key, {}});
    at->second.results.push_back(&r);
    for (const std::string& e : r.check.engines) {
      auto& list = at->second.engines;
      if (std::find(list.begin(), list.end(), e) == list.end()) list.push_back(e);
    }
  }
  return scenes;
}

// Evaluates the scene's checks on the comparison without the term.
void judge(GateTermEffect& effect, const SceneChecks& checks, const Comparison& without) {
  effect.all_within = true;
  double largest = 0.0;
  for (const CheckResult* with : checks.results) {
    const CheckResult r = evaluateCheck(with->check, without);
    if (!r.passed || !r.measured || !with->measured) {
      effect.all_within = false;
      largest = INFINITY;
      continue;
    }
    const double change = std::abs(*r.measured - *with->measured);
    const double bound = with->check.bound;
    if (change > bound) effect.all_within = false;
    largest = std::max(largest, bound > 0 ? change / bound : (change > 0 ? INFINITY : 0.0));
  }
  effect.largest_share = largest;
}

std::expected<GateTermEffect, std::string> ablateTerm(const EngineRegistry& registry,
                                                      const SceneChecks& checks, json scene,
                                                      const mysim::ModelTerm& term) {
  const ToleranceCheck& first = checks.results.front()->check;
  GateTermEffect effect{first.scene.substr(first.scene.find_last_of('/') + 1) +
                            first.variantLabel(),
                        term.name, sceneDeclares(scene, term.name)};
  effect.checks = checks.results.size();
  term.remove(scene);
  scene.erase("needs");  // the variant lacks a term the scene may declare
  auto parsed = mysim::parseScene(scene.dump(), first.scene, registry.sceneSections());
  if (!parsed) {
    effect.problem = "without " + term.name + " the scene does not load: " + parsed.error();
    return effect;
  }
  auto comparison = compareScene(registry, *parsed, checks.engines);
  if (!comparison) return std::unexpected(first.scene + ": " + comparison.error());
  effect.ran = true;
  judge(effect, checks, *comparison);
  return effect;
}

}  // namespace

std::expected<std::vector<GateTermEffect>, std::string> ablateGate(const EngineRegistry& registry,
                                                                   const GateReport& report) {
  std::vector<GateTermEffect> effects;
  for (const auto& [key, checks] : byScene(report)) {
    auto scene = sceneVariantJson(checks.results.front()->check);
    if (!scene) return std::unexpected(scene.error());
    for (const mysim::ModelTerm& term : mysim::modelTerms()) {
      if (!term.present(*scene)) continue;
      auto effect = ablateTerm(registry, checks, *scene, term);
      if (!effect) return std::unexpected(effect.error());
      effects.push_back(std::move(*effect));
    }
  }
  return effects;
}

void printGateAblation(std::ostream& out, const std::vector<GateTermEffect>& effects) {
  out << "ablation: each model term a gated scene carries, taken out (docs/trade.md)\n";
  if (effects.empty()) out << "  no gated scene carries a term an ablation takes out\n";
  for (const GateTermEffect& e : effects) {
    out << "  " << e.scene << " without " << e.term << ": ";
    const bool finite = e.largest_share && std::isfinite(*e.largest_share);
    const std::string share = finite ? formatNumber(100.0 * *e.largest_share, 3) + " %" : "";
    if (!e.ran) {
      out << e.problem;
    } else if (e.all_within) {
      out << "all " << e.checks << " checks still pass, each changed by at most " << share
          << " of its bound" << (e.declared ? "; its needs declare it: kept" : ": not needed");
    } else {
      out << "needed (" << (finite ? "a check changed by " + share + " of its bound" : "a check fails")
          << ")";
    }
    out << '\n';
  }
}

}  // namespace springcheck
