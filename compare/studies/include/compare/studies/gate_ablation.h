#pragma once
// Which model terms a gated scene carries but none of its checks needs (docs/trade.md,
// "Ablation"): each scene of a tolerances file (each variant apart) rerun in the engines its
// checks name with each term of mysim's catalogue (model_terms.h) taken out, and its checks
// evaluated again. A term every check still passes without, each changed by at most its bound,
// is one the scene could drop, unless its `needs` declare it.
#include <expected>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/studies/gate.h"

namespace springcheck {

struct GateTermEffect {
  std::string scene;  // the check's scene and variant, as printGate names it
  std::string term;
  bool declared = false;  // the scene's `needs` name it
  bool ran = false;       // false: the variant did not load (`problem` says why)
  std::string problem;
  std::size_t checks = 0;  // the scene's checks
  bool all_within = false;  // every check passes without the term, each changed <= its bound
  // The largest |change| / bound over the checks (0 when every bound is 0 and nothing moved).
  std::optional<double> largest_share;
  bool droppable() const { return ran && all_within && !declared; }
};

// `report`: the gate's results (the values with every term); its checks say what to rerun.
[[nodiscard]] std::expected<std::vector<GateTermEffect>, std::string> ablateGate(
    const EngineRegistry& registry, const GateReport& report);

void printGateAblation(std::ostream& out, const std::vector<GateTermEffect>& effects);

}  // namespace springcheck
