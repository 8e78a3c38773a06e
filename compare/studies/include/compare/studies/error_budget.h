#pragma once
// The error budget of each setup of a trade grid (the parts: trade.h, ErrorBudget), and the
// converged runs it is measured from.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "compare/studies/trade.h"

namespace springcheck {

// How much solving an integrator variant does per step: the product of its integer catalogue
// parameters (passes, substeps, iteration limits), each at its value or default; 1 for an engine
// without an integrator. Within one integrator, the variant with the most is the converged one.
double solverEffort(const std::string& integrator);
// The integrator's name without its parameters ("xpbd:substeps=4" -> "xpbd"; "-" stays).
std::string integratorBase(const std::string& integrator);

// The grid's converged runs: per (resolution, engine, integrator base), the most converged
// variant, its value at each step, and its smallest step.
class ConvergedRuns {
 public:
  explicit ConvergedRuns(const std::vector<TradeSetup>& setups);
  // The limit of each engine and converged integrator over the resolutions, at its smallest step.
  std::vector<FamilyLimit> limits(const std::string& quantity) const;
  // Fills s.budget against `reference` (the physical one) and each family's limit.
  void budget(TradeSetup& s, const PhysicalReference& reference,
              const std::vector<FamilyLimit>& limits) const;

 private:
  using Key = std::tuple<int, std::string, std::string>;  // resolution, engine, base
  struct Best {
    std::string variant;
    double effort = 0.0;
    std::map<double, double> value_at_dt;  // the variant's settled values by step
  };
  std::map<Key, Best> best_;
};

}  // namespace springcheck
