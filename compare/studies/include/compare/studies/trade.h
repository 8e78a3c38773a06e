#pragma once
// The trade against physical truth (docs/trade.md): every setup of a joint grid (resolution x
// engine x integrator and its parameters x step) run on a material scene, each setup's settled
// quantity held against the physical reference (physical_reference.h), its error split into a
// budget (error_budget.h), and the answer: the cheapest setup within a bound, the runner-up, the
// Pareto front per solver family and Bullet's best.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compare/studies/physical_reference.h"
#include "compare/studies/recommend.h"
#include "compare/studies/sweep_table.h"

namespace springcheck {

// A setup's physical error split along a path of runs from it to the reference, each part a
// measured difference of the quantity (docs/trade.md, "The budget"):
//   solver   = q(setup) - q(same resolution, engine and dt, the grid's most converged solver)
//   temporal = that - q(same, at the grid's smallest step)
//   spatial  = that - the Richardson limit of those converged runs over the grid's resolutions
//   model    = that limit - the physical reference (0 when the reference is this very limit)
// A part that could not be measured (its converged run blew up, too few resolutions for a limit)
// is absent, and what it holds is left in the remainder: total - the parts measured.
struct ErrorBudget {
  std::optional<double> solver, temporal, spatial, model;
  double remainder = 0.0;
  std::string how;  // which runs each part came from
};

struct TradeSetup {
  int resolution = 0;
  std::string engine, integrator, family;  // integrator "-" for engines without one
  double dt = 0.0;
  std::string status;  // the run's (ok, blowup, refused, ...)
  std::optional<double> blowup_time;
  std::optional<double> value, drift;  // the quantity at the end; its change over the last tenth
  std::optional<double> physical_error;  // value - reference, the quantity's unit
  bool settled = false;  // ran to the end with |drift| <= kSettledFraction x the bound
  double wall_seconds = 0.0;
  long work = 0;  // derivative evaluations + linear iterations (machine-independent)
  ErrorBudget budget;
  std::string excluded;  // why it is never recommended (empty: eligible)
};

// A setup settles when its quantity moved over the run's last tenth by at most this fraction of
// the bound: what is left of an exponential approach that moved d in the last tenth is about d
// again at the slowest rate the shipped scenes' damping gives, so a tenth of the bound keeps the
// settling error an order of magnitude inside it.
constexpr double kSettledFraction = 0.1;

struct TradeQuestion {
  std::string quantity;
  double max_error = 0.0;  // as given: in the quantity's unit, or a fraction with `relative`
  bool relative = false;
  Cost cost = Cost::WallTime;
};

struct TradeInputs {
  std::vector<SweepRow> rows;                      // the grid's table
  std::map<std::string, int> resolution_of_scene;  // the table's scene names -> resolution
  std::optional<PhysicalReference> closed_form;    // the scene's, when it has one
  // Without a closed form the reference is this engine and integrator's limit (its most
  // converged solver at the smallest step, over the grid's resolutions).
  std::string reference_engine, reference_integrator;
  std::function<bool(const std::string& engine)> is_bullet = nullptr;
};

struct FamilyLimit {
  std::string engine, integrator;  // the converged variant the limit is of
  PhysicalReference limit;
};

struct TradeAnswer {
  PhysicalReference reference;
  double bound = 0.0;  // absolute, in the quantity's unit
  std::vector<TradeSetup> setups;
  std::optional<std::size_t> recommended, runner_up, closest, bullet_best;
  std::vector<std::size_t> family_best;  // each family's cheapest within the bound, cheapest first
  std::map<std::string, std::vector<std::size_t>> pareto;  // per family, cheapest first
  std::vector<FamilyLimit> limits;
  int blew_up = 0, unsettled = 0;  // setups excluded for these
};

TradeAnswer analyseTrade(const TradeInputs& inputs, const TradeQuestion& question);

// "resolution 16, mysim vbd:iterations=40, dt 0.004 s: 0.41 % (1.2e-4 m) in 0.031 s".
std::string describeSetup(const TradeSetup& s, const TradeAnswer& a);

}  // namespace springcheck
