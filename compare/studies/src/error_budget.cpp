#include "compare/studies/error_budget.h"

#include <cmath>

#include "compare/io/text_format.h"
#include "mysim/integrator.h"

namespace springcheck {

std::string integratorBase(const std::string& integrator) {
  return integrator.substr(0, integrator.find(':'));
}

double solverEffort(const std::string& integrator) {
  if (integrator.empty() || integrator == "-") return 1.0;
  const auto variant = mysim::parseIntegratorVariant(integrator);
  if (!variant) return 1.0;
  double effort = 1.0;
  for (const mysim::IntegratorParameter& p : mysim::findIntegrator(variant->name)->parameters) {
    if (!p.in_values || !p.integer) continue;
    const auto set = variant->values.find(p.name);
    effort *= set != variant->values.end() ? set->second : std::stod(p.fallback);
  }
  return effort;
}

ConvergedRuns::ConvergedRuns(const std::vector<TradeSetup>& setups) {
  for (const TradeSetup& s : setups) {
    if (!s.settled || !s.value) continue;
    Best& best = best_[{s.resolution, s.engine, integratorBase(s.integrator)}];
    const double effort = solverEffort(s.integrator);
    if (best.variant.empty() || effort > best.effort) {
      best = Best{s.integrator, effort, {}};
    }
    if (s.integrator == best.variant) best.value_at_dt[s.dt] = *s.value;
  }
}

std::vector<FamilyLimit> ConvergedRuns::limits(const std::string& quantity) const {
  // Per engine and base: the converged value at each resolution (at its own smallest step).
  std::map<std::pair<std::string, std::string>, std::pair<std::vector<int>, std::vector<double>>>
      series;
  std::map<std::pair<std::string, std::string>, std::string> variant;
  for (const auto& [key, best] : best_) {
    const auto& [resolution, engine, base] = key;
    auto& [n, q] = series[{engine, base}];
    n.push_back(resolution);
    q.push_back(best.value_at_dt.begin()->second);  // the smallest step
    variant[{engine, base}] = best.variant;
  }
  std::vector<FamilyLimit> out;
  for (const auto& [key, nq] : series) {
    const std::string of = key.first + (key.second == "-" ? "" : " " + key.second) +
                           " at its most converged solver and smallest step";
    out.push_back({key.first, variant[key], refinementReference(quantity, nq.first, nq.second, of)});
  }
  return out;
}

void ConvergedRuns::budget(TradeSetup& s, const PhysicalReference& reference,
                           const std::vector<FamilyLimit>& limits) const {
  if (!s.physical_error || !s.value) return;
  ErrorBudget& b = s.budget;
  const auto it = best_.find({s.resolution, s.engine, integratorBase(s.integrator)});
  if (it == best_.end()) {
    b.remainder = *s.physical_error;
    b.how = "no converged run of this engine and integrator at this resolution settled";
    return;
  }
  const Best& best = it->second;
  double at = *s.value;  // where the path has got to
  if (auto same_dt = best.value_at_dt.find(s.dt); same_dt != best.value_at_dt.end()) {
    b.solver = at - same_dt->second;
    at = same_dt->second;
    b.how = "solver against " + best.variant + " at dt " + formatNumber(s.dt, 4) + " s";
  } else {
    b.how = "solver not measured (" + best.variant + " at dt " + formatNumber(s.dt, 4) +
            " s did not settle)";
  }
  const auto& [dt_min, converged] = *best.value_at_dt.begin();
  b.temporal = at - converged;
  at = converged;
  b.how += "; temporal against dt " + formatNumber(dt_min, 4) + " s";
  for (const FamilyLimit& f : limits) {
    if (f.engine != s.engine || integratorBase(f.integrator) != integratorBase(s.integrator) ||
        !f.limit.value) {
      continue;
    }
    b.spatial = at - *f.limit.value;
    b.model = *f.limit.value - *reference.value;
    b.how += "; spatial against its " + f.limit.source + "; model: that limit against the " +
             reference.source;
  }
  if (!b.spatial) b.how += "; spatial and model not separated (no limit of this family)";
  b.remainder = *s.physical_error - (b.solver.value_or(0.0) + b.temporal.value_or(0.0) +
                                     b.spatial.value_or(0.0) + b.model.value_or(0.0));
}

}  // namespace springcheck
