#include "trade_output.h"

#include <cmath>
#include <iostream>
#include <sstream>

#include "compare/io/csv.h"
#include "compare/io/text_format.h"
#include "mysim/integrator.h"

namespace springcheck {
namespace {

using nlohmann::json;

std::string number(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? formatNumber(*v, 10) : "";
}

json optionalNumber(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? json(*v) : json(nullptr);
}

json budgetJson(const ErrorBudget& b) {
  return {{"solver", optionalNumber(b.solver)},       {"temporal", optionalNumber(b.temporal)},
          {"spatial", optionalNumber(b.spatial)},     {"model", optionalNumber(b.model)},
          {"remainder", b.remainder},                 {"how", b.how}};
}

// The integrator's parameters as numbers, each at its value or default ({} without one).
json integratorParameters(const std::string& integrator) {
  json out = json::object();
  const auto variant = mysim::parseIntegratorVariant(integrator);
  if (integrator == "-" || !variant) return out;
  for (const mysim::IntegratorParameter& p : mysim::findIntegrator(variant->name)->parameters) {
    if (!p.in_values) continue;
    const auto set = variant->values.find(p.name);
    out[p.name] = set != variant->values.end() ? set->second : std::stod(p.fallback);
  }
  return out;
}

json setupJson(const TradeAnswer& a, const std::optional<std::size_t>& k) {
  if (!k) return nullptr;
  const TradeSetup& s = a.setups[*k];
  const double rel = s.physical_error && *a.reference.value != 0.0
                         ? *s.physical_error / *a.reference.value
                         : NAN;
  return {{"resolution", s.resolution},
          {"engine", s.engine},
          {"integrator", s.integrator},
          {"family", s.family},
          {"parameters", integratorParameters(s.integrator)},
          {"dt", s.dt},
          {"value", optionalNumber(s.value)},
          {"reference", optionalNumber(a.reference.value)},
          {"physical_error", optionalNumber(s.physical_error)},
          {"relative_error", optionalNumber(rel)},
          {"budget", budgetJson(s.budget)},
          {"wall_seconds", s.wall_seconds},
          {"work", s.work},
          {"summary", describeSetup(s, a)}};
}

json referenceJson(const PhysicalReference& r) {
  return {{"value", optionalNumber(r.value)},      {"uncertainty", r.uncertainty},
          {"closed_form", r.closed_form},          {"order", optionalNumber(r.order)},
          {"coarser_order", optionalNumber(r.coarser_order)},
          {"source", r.source},                    {"warning", r.warning},
          {"reason", r.reason}};
}

}  // namespace

std::string tradeTableCsv(const TradeAnswer& a) {
  std::ostringstream out;
  out << csvLine({"resolution", "engine", "integrator", "family", "dt", "status", "blowup_time",
                  "settled", "value", "drift_last_tenth", "reference", "physical_error",
                  "relative_error", "solver_part", "temporal_part", "spatial_part", "model_part",
                  "remainder", "wall_seconds", "work", "excluded"})
      << '\n';
  for (const TradeSetup& s : a.setups) {
    const std::optional<double> rel =
        s.physical_error && a.reference.value && *a.reference.value != 0.0
            ? std::optional(*s.physical_error / *a.reference.value)
            : std::nullopt;
    out << csvLine({std::to_string(s.resolution), s.engine, s.integrator, s.family,
                    formatNumber(s.dt, 10), s.status, number(s.blowup_time),
                    s.settled ? "1" : "0", number(s.value), number(s.drift),
                    number(a.reference.value), number(s.physical_error), number(rel),
                    number(s.budget.solver), number(s.budget.temporal), number(s.budget.spatial),
                    number(s.budget.model),
                    s.physical_error ? formatNumber(s.budget.remainder, 10) : "",
                    formatNumber(s.wall_seconds, 10), std::to_string(s.work), s.excluded})
        << '\n';
  }
  return out.str();
}

json tradeJson(const TradeAnswer& a, const TradeReport& r) {
  json families = json::array(), fronts = json::object(), limits = json::array();
  for (std::size_t k : a.family_best) families.push_back(setupJson(a, k));
  for (const auto& [family, front] : a.pareto) {
    for (std::size_t k : front) fronts[family].push_back(setupJson(a, k));
  }
  for (const FamilyLimit& f : a.limits) {
    limits.push_back({{"engine", f.engine}, {"integrator", f.integrator},
                      {"limit", referenceJson(f.limit)}});
  }
  json ratio = nullptr;
  if (a.recommended && a.bullet_best && a.setups[*a.recommended].wall_seconds > 0) {
    ratio = a.setups[*a.bullet_best].wall_seconds / a.setups[*a.recommended].wall_seconds;
  }
  return {{"scene", r.scene},
          {"quantity", r.quantity},
          {"unit", r.unit},
          {"max_error", r.question.max_error},
          {"relative", r.question.relative},
          {"bound", a.bound},
          {"cost", r.question.cost == Cost::Work ? "work" : "wall_seconds"},
          {"reference", referenceJson(a.reference)},
          {"recommended", setupJson(a, a.recommended)},
          {"runner_up", setupJson(a, a.runner_up)},
          {"closest", setupJson(a, a.closest)},
          {"bullet_best", setupJson(a, a.bullet_best)},
          {"bullet_over_recommended_wall", ratio},
          {"family_best", families},
          {"pareto", fronts},
          {"family_limits", limits},
          {"setups", a.setups.size()},
          {"blew_up", a.blew_up},
          {"unsettled", a.unsettled},
          {"table", r.table}};
}

}  // namespace springcheck

namespace springcheck {
namespace {

std::string signedNumber(const std::optional<double>& v) {
  if (!v) return "not measured";
  return (*v >= 0 ? "+" : "") + formatNumber(*v, 2);
}

void printBudget(const TradeSetup& s) {
  if (!s.physical_error) return;
  const ErrorBudget& b = s.budget;
  std::cout << "      budget: solver " << signedNumber(b.solver) << ", temporal "
            << signedNumber(b.temporal) << ", spatial " << signedNumber(b.spatial) << ", model "
            << signedNumber(b.model) << ", remainder " << signedNumber(b.remainder) << " (total "
            << signedNumber(s.physical_error) << ")\n";
}

}  // namespace

void printTradeAnswer(const TradeAnswer& a, const TradeReport& r) {
  const std::string bound = r.question.relative
                                ? formatNumber(100.0 * r.question.max_error, 3) + " %"
                                : formatNumber(r.question.max_error, 3) + " " + r.unit;
  std::cout << r.scene << ": " << r.quantity << " [" << r.unit << "] within " << bound << " of ";
  if (!a.reference.value) {
    std::cout << "its physical reference: none (" << a.reference.reason << ")\n";
    return;
  }
  std::cout << formatNumber(*a.reference.value, 6) << " (" << a.reference.source;
  if (!a.reference.closed_form) std::cout << ", +- " << formatNumber(a.reference.uncertainty, 2);
  std::cout << "), bound " << formatNumber(a.bound, 3) << " " << r.unit << ", cheapest by "
            << (r.question.cost == Cost::Work ? "work" : "wall time") << ":\n";
  if (!a.reference.warning.empty()) {
    std::cout << "  warning: the limit is not to be trusted: " << a.reference.warning << '\n';
  }
  if (a.recommended) {
    std::cout << "  recommended: " << describeSetup(a.setups[*a.recommended], a) << '\n';
    printBudget(a.setups[*a.recommended]);
    std::cout << "  runner-up:   "
              << (a.runner_up ? describeSetup(a.setups[*a.runner_up], a) : "none") << '\n';
  } else {
    std::cout << "  no setup of the grid is within the bound; the closest: "
              << (a.closest ? describeSetup(a.setups[*a.closest], a) : "none settled") << '\n';
    if (a.closest) printBudget(a.setups[*a.closest]);
  }
  if (a.bullet_best) {
    const TradeSetup& b = a.setups[*a.bullet_best];
    std::cout << "  Bullet's best: " << describeSetup(b, a);
    if (a.recommended && a.setups[*a.recommended].wall_seconds > 0) {
      std::cout << " (" << formatNumber(b.wall_seconds / a.setups[*a.recommended].wall_seconds, 3)
                << "x the recommended's wall time)";
    }
    std::cout << '\n';
  } else {
    std::cout << "  Bullet's best: no Bullet setup of the grid is within the bound\n";
  }
  if (!a.family_best.empty()) std::cout << "  each family's cheapest within the bound:\n";
  for (std::size_t k : a.family_best) {
    std::cout << "    " << a.setups[k].family << ": " << describeSetup(a.setups[k], a) << '\n';
  }
  std::cout << "  " << a.setups.size() << " setups; never recommended: " << a.blew_up
            << " blew up, " << a.unsettled << " did not settle (" << r.table
            << ", column excluded, says why for each)\n";
}

}  // namespace springcheck
