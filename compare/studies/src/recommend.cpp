#include "compare/studies/recommend.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "mysim/integrator.h"

namespace springcheck {
std::string solverFamily(const std::string& engine, const std::string& integrator) {
  if (integrator.empty() || integrator == "-") return engine;
  const auto variant = mysim::parseIntegratorVariant(integrator);
  return variant ? mysim::familyName(mysim::findIntegrator(variant->name)->family) : integrator;
}

namespace {

// Each key's first choice, in order (the list is cheapest first, so each first is the best).
template <typename Key>
std::vector<Choice> firstOfEach(const std::vector<Choice>& sorted, Key key) {
  std::vector<Choice> out;
  for (const Choice& c : sorted) {
    if (std::none_of(out.begin(), out.end(), [&](const Choice& seen) { return key(seen) == key(c); })) {
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace

std::vector<Recommendation> recommend(const std::vector<SweepRow>& rows, double max_error,
                                      Cost cost) {
  std::vector<std::pair<std::string, double>> order;  // groups in the table's order
  std::map<std::pair<std::string, double>, std::vector<Choice>> groups;
  for (const SweepRow& row : rows) {
    const std::pair<std::string, double> key{row.c.scene, row.c.stiffness_scale};
    if (!groups.count(key)) order.push_back(key);
    auto& group = groups[key];
    if (row.status != "ok" || !row.error) continue;
    Choice c;
    c.engine = row.c.engine;
    c.integrator = row.c.integrator;
    c.family = solverFamily(c.engine, c.integrator);
    c.tolerance = sweepField(row, "tolerance");
    c.dt = row.c.dt;
    c.error = *row.error;
    c.wall_seconds = row.wall_seconds.value_or(0.0);
    c.realtime_factor = row.realtime_factor.value_or(0.0);
    c.work = row.derivative_evaluations.value_or(0) + row.linear_iterations.value_or(0);
    c.reference = row.reference;
    group.push_back(c);
  }
  std::vector<Recommendation> out;
  for (const auto& key : order) {
    Recommendation r;
    r.scene = key.first;
    r.stiffness_scale = key.second;
    r.max_error = max_error;
    r.cost = cost;
    std::vector<Choice> meeting;
    for (const Choice& c : groups[key]) {
      ++r.candidates;
      if (c.error <= max_error) meeting.push_back(c);
    }
    r.meeting = static_cast<int>(meeting.size());
    auto price = [&](const Choice& c) {
      return cost == Cost::Work ? static_cast<double>(c.work) : c.wall_seconds;
    };
    std::stable_sort(meeting.begin(), meeting.end(), [&](const Choice& a, const Choice& b) {
      if (price(a) != price(b)) return price(a) < price(b);
      return a.dt > b.dt;
    });
    if (!meeting.empty()) r.best = meeting[0];
    if (meeting.size() > 1) r.runner_up = meeting[1];
    r.per_engine = firstOfEach(meeting, [](const Choice& c) { return c.engine; });
    r.per_family = firstOfEach(meeting, [](const Choice& c) { return c.family; });
    std::vector<Choice> by_error = groups[key];
    std::stable_sort(by_error.begin(), by_error.end(),
                     [](const Choice& a, const Choice& b) { return a.error < b.error; });
    r.closest_per_family = firstOfEach(by_error, [](const Choice& c) { return c.family; });
    out.push_back(r);
  }
  return out;
}

std::string describe(const Choice& c) {
  char text[400];
  const std::string what =
      c.integrator == "-" || c.integrator.empty() ? c.engine : c.engine + " with " + c.integrator;
  std::snprintf(text, sizeof text,
                "%s%s at dt %g s: error %.3g m, %.3g s of stepping (%.3gx realtime), %ld "
                "evaluations and iterations",
                what.c_str(),
                c.tolerance.empty() ? "" : (" (tolerance " + c.tolerance + ")").c_str(), c.dt,
                c.error, c.wall_seconds, c.realtime_factor, c.work);
  return text;
}

}  // namespace springcheck
