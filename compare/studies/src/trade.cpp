#include "compare/studies/trade.h"

#include <algorithm>
#include <cmath>

#include "compare/io/text_format.h"
#include "compare/studies/error_budget.h"

namespace springcheck {
namespace {

// The bound a setup's settling is judged by: the absolute bound, or the relative one at the
// setup's own value (the reference is not known yet when the converged runs are picked).
double settlingBound(const TradeQuestion& q, double value) {
  return q.relative ? q.max_error * std::abs(value) : q.max_error;
}

std::vector<TradeSetup> setupsOf(const TradeInputs& in, const TradeQuestion& q) {
  std::vector<TradeSetup> out;
  for (const SweepRow& row : in.rows) {
    const auto resolution = in.resolution_of_scene.find(row.c.scene);
    if (resolution == in.resolution_of_scene.end()) continue;
    TradeSetup s;
    s.resolution = resolution->second;
    s.engine = row.c.engine;
    s.integrator = row.c.integrator;
    s.family = solverFamily(s.engine, s.integrator);
    s.dt = row.c.dt;
    s.status = row.status;
    s.blowup_time = row.blowup_time;
    s.wall_seconds = row.wall_seconds.value_or(0.0);
    s.work = row.derivative_evaluations.value_or(0) + row.linear_iterations.value_or(0);
    if (auto it = row.quantities.find(q.quantity); it != row.quantities.end()) {
      s.value = it->second.end;
      s.drift = it->second.drift();
    }
    if (row.status == "blowup") {
      s.excluded = "blew up at t = " + formatNumber(row.blowup_time.value_or(0.0), 4) + " s (" +
                   row.blowup_check + ")";
    } else if (row.status != "ok") {
      s.excluded = row.status + (row.note.empty() ? "" : ": " + row.note);
    } else if (!s.value) {
      s.excluded = "no " + q.quantity + " in this run";
    } else if (std::abs(*s.drift) > kSettledFraction * settlingBound(q, *s.value)) {
      s.excluded = "did not settle: " + q.quantity + " still moved by " +
                   formatNumber(std::abs(*s.drift), 3) + " over the run's last tenth";
    } else {
      s.settled = true;
    }
    out.push_back(s);
  }
  return out;
}

PhysicalReference chooseReference(const TradeInputs& in, const std::vector<FamilyLimit>& limits,
                                  const std::string& quantity) {
  if (in.closed_form) return *in.closed_form;
  for (const FamilyLimit& f : limits) {
    if (f.engine == in.reference_engine &&
        integratorBase(f.integrator) == integratorBase(in.reference_integrator)) {
      return f.limit;
    }
  }
  PhysicalReference none;
  none.quantity = quantity;
  none.reason = "no closed form, and " + in.reference_engine + " " + in.reference_integrator +
                " settled at no resolution of the grid";
  return none;
}

// Cheapest first by the question's cost; ties to the larger step, then the coarser resolution.
std::vector<std::size_t> byCost(const TradeAnswer& a, const std::vector<std::size_t>& which,
                                Cost cost) {
  std::vector<std::size_t> order = which;
  auto price = [&](std::size_t k) {
    return cost == Cost::Work ? static_cast<double>(a.setups[k].work) : a.setups[k].wall_seconds;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if (price(x) != price(y)) return price(x) < price(y);
    if (a.setups[x].dt != a.setups[y].dt) return a.setups[x].dt > a.setups[y].dt;
    return a.setups[x].resolution < a.setups[y].resolution;
  });
  return order;
}

void paretoFronts(TradeAnswer& a, const std::vector<std::size_t>& eligible_by_cost) {
  std::map<std::string, double> best_error;
  for (std::size_t k : eligible_by_cost) {
    const TradeSetup& s = a.setups[k];
    const double e = std::abs(*s.physical_error);
    auto it = best_error.find(s.family);
    if (it == best_error.end() || e < it->second) {
      best_error[s.family] = e;
      a.pareto[s.family].push_back(k);
    }
  }
}

void choose(TradeAnswer& a, const TradeInputs& in, Cost cost) {
  std::vector<std::size_t> eligible;
  for (std::size_t k = 0; k < a.setups.size(); ++k) {
    if (a.setups[k].excluded.empty() && a.setups[k].physical_error) eligible.push_back(k);
  }
  const std::vector<std::size_t> ordered = byCost(a, eligible, cost);
  paretoFronts(a, ordered);
  std::vector<std::string> families;
  for (std::size_t k : ordered) {
    const TradeSetup& s = a.setups[k];
    const double e = std::abs(*s.physical_error);
    if (!a.closest || e < std::abs(*a.setups[*a.closest].physical_error)) a.closest = k;
    if (e > a.bound) continue;
    if (!a.recommended) {
      a.recommended = k;
    } else if (!a.runner_up) {
      a.runner_up = k;
    }
    if (std::find(families.begin(), families.end(), s.family) == families.end()) {
      families.push_back(s.family);
      a.family_best.push_back(k);
    }
    if (!a.bullet_best && in.is_bullet && in.is_bullet(s.engine)) a.bullet_best = k;
  }
}

}  // namespace

TradeAnswer analyseTrade(const TradeInputs& in, const TradeQuestion& q) {
  TradeAnswer a;
  a.setups = setupsOf(in, q);
  for (const TradeSetup& s : a.setups) {
    a.blew_up += s.status == "blowup";
    a.unsettled += s.status == "ok" && s.value && !s.settled;
  }
  const ConvergedRuns converged(a.setups);
  a.limits = converged.limits(q.quantity);
  a.reference = chooseReference(in, a.limits, q.quantity);
  if (!a.reference.value) return a;
  a.bound = q.relative ? q.max_error * std::abs(*a.reference.value) : q.max_error;
  for (TradeSetup& s : a.setups) {
    if (!s.value) continue;
    s.physical_error = *s.value - *a.reference.value;
    converged.budget(s, a.reference, a.limits);
  }
  choose(a, in, q.cost);
  return a;
}

std::string describeSetup(const TradeSetup& s, const TradeAnswer& a) {
  // "resolution", not "cells": a chain counts links, a disc rings (the report says the same).
  std::string text = "resolution " + std::to_string(s.resolution) + ", " + s.engine +
                     (s.integrator == "-" ? "" : " " + s.integrator) + ", dt " +
                     formatNumber(s.dt, 4) + " s";
  if (s.physical_error && a.reference.value && *a.reference.value != 0.0) {
    text += ": " + formatNumber(100.0 * std::abs(*s.physical_error / *a.reference.value), 2) +
            " % (" + formatNumber(std::abs(*s.physical_error), 2) + ")";
  }
  return text + " in " + formatNumber(s.wall_seconds, 2) + " s";
}

}  // namespace springcheck
