// What `springcheck trade --ablate` prints and writes (trade_output.h).
#include <cmath>
#include <iostream>

#include "compare/io/text_format.h"
#include "trade_output.h"

namespace springcheck {
namespace {

using nlohmann::json;

json runJson(const AblationRun& r, const AblationRun& full) {
  const bool both = r.value && full.value;
  return {{"term", r.term},
          {"description", r.description},
          {"status", r.status},
          {"value", r.value ? json(*r.value) : json(nullptr)},
          {"change", both ? json(*r.value - *full.value) : json(nullptr)},
          {"settled", r.settled},
          {"within_bound", r.within},
          {"declared_needed", r.declared},
          {"wall_seconds", r.wall_seconds}};
}

void printRun(const AblationRun& r, const AblationRun& full) {
  std::cout << "    without " << r.term << " (" << r.description << "): ";
  if (!r.value) {
    std::cout << r.status << ", no value\n";
    return;
  }
  std::cout << "changes it by " << formatNumber(*r.value - full.value.value_or(NAN), 3) << " ("
            << (r.within ? "still within the bound" : r.settled ? "outside the bound"
                                                                : "does not settle")
            << (r.declared ? "; the scene's needs declare it: kept" : "") << "), " << formatNumber(r.wall_seconds, 3) << " s against "
            << formatNumber(full.wall_seconds, 3) << " s\n";
}

}  // namespace

void printAblation(const Ablation& a, const std::string& where) {
  std::cout << "  ablation at " << where << ":\n";
  for (const AblationRun& r : a.without) printRun(r, a.full);
  if (a.without.empty()) std::cout << "    the scene carries none of the terms an ablation takes out\n";
  for (const AblationRun& r : a.without) {
    if (r.within && !r.declared) {
      std::cerr << "warning: the scene carries " << r.term << " but the quantity stays within the "
                << "bound without it; drop it, or declare it in the scene's \"needs\" "
                << "(docs/trade.md)\n";
    }
  }
  if (a.cheapest) {
    std::cout << "  the cheapest model within the bound: without " << a.cheapest->term << ", "
              << (a.cheapest->within ? "within" : "NOT within (the terms interact)") << ", "
              << formatNumber(a.cheapest->wall_seconds, 3) << " s\n";
  } else if (!a.without.empty()) {
    std::cout << "  every term matters: taking any out leaves the bound or the settling\n";
  }
}

json ablationJson(const Ablation& a) {
  json without = json::array();
  for (const AblationRun& r : a.without) without.push_back(runJson(r, a.full));
  return {{"full", runJson(a.full, a.full)},
          {"without", without},
          {"cheapest_model", a.cheapest ? runJson(*a.cheapest, a.full) : json(nullptr)}};
}

}  // namespace springcheck
