#pragma once
// Model only what a scene requires (docs/trade.md, "Ablation"): the setup a trade recommends,
// rerun with each model term the scene carries taken out (bending, material damping, drag, wind,
// colliders, driven pins), each term's effect on the settled quantity against the bound, and the
// cheapest model that stays within it. The terms come from mysim's catalogue (model_terms.h).
#include <expected>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "compare/engines/engine_registry.h"
#include "compare/studies/trade.h"

namespace springcheck {

struct AblationRun {
  std::string term;         // "" for the scene as written; "a+b" for terms taken out together
  std::string description;  // what taking it out means
  std::string status;       // the run's (ok, blowup, refused, ...)
  std::optional<double> value, drift;
  bool settled = false;
  double wall_seconds = 0.0;
  // |value - reference| <= bound, settled: the model without the term still answers
  bool within = false;
  bool declared = false;  // the scene's `needs` name the term: kept whatever it measures
};

struct Ablation {
  AblationRun full;                  // the scene as written, at the setup
  std::vector<AblationRun> without;  // each term present, taken out alone
  // Every term that can go (within the bound without it, not declared in `needs`), taken out
  // together: the cheapest model. Its terms are the ones the scene carries but does not need.
  std::optional<AblationRun> cheapest;
};

// Whether a scene file's `needs` name the model term (model_terms.h): a declared term is kept.
bool sceneDeclares(const nlohmann::json& scene, const std::string& term);

// At `setup` (its resolution, engine, integrator and step) of the material scene at `path`;
// `reference` and `bound` (absolute) from the trade's answer.
[[nodiscard]] std::expected<Ablation, std::string> ablate(const EngineRegistry& registry,
                                                          const std::string& path,
                                                          const TradeSetup& setup,
                                                          const std::string& quantity,
                                                          double reference, double bound);

}  // namespace springcheck
