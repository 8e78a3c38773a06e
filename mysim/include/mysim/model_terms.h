#pragma once
// The model terms a scene can carry and an ablation can take out (docs/trade.md, "Ablation"):
// one row each, how to see it in a scene file and how to take it out. The only list of them:
// the scene reader checks a scene's `needs` against it, compare's ablation walks it.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mysim {

struct ModelTerm {
  std::string name;         // as a scene's `needs` names it
  std::string description;  // what taking it out means
  std::function<bool(const nlohmann::json&)> present;  // the scene file carries it
  std::function<void(nlohmann::json&)> remove;         // the scene file without it
};

const std::vector<ModelTerm>& modelTerms();
const ModelTerm* findModelTerm(const std::string& name);
std::string modelTermNames();  // "bending, damping, ..." for messages

}  // namespace mysim
