#include "compare/studies/recommend.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace springcheck {
namespace {

double numberOr(const std::string& text, double fallback) {
  try {
    return text.empty() ? fallback : std::stod(text);
  } catch (const std::exception&) {
    return fallback;
  }
}

}  // namespace

std::vector<Recommendation> recommend(const std::vector<SweepRow>& rows, double max_error,
                                      Cost cost) {
  auto at = [](const SweepRow& row, const char* name) -> const std::string& {
    return row[sweepColumn(name)];
  };
  std::vector<std::pair<std::string, double>> order;  // groups in the table's order
  std::map<std::pair<std::string, double>, std::vector<Choice>> groups;
  for (const SweepRow& row : rows) {
    const std::pair<std::string, double> key{at(row, "scene"),
                                             numberOr(at(row, "stiffness_scale"), 1.0)};
    if (!groups.count(key)) order.push_back(key);
    auto& group = groups[key];
    if (at(row, "status") != "ok" || at(row, "error").empty()) continue;
    Choice c;
    c.engine = at(row, "engine");
    c.integrator = at(row, "integrator");
    c.tolerance = at(row, "tolerance");
    c.dt = numberOr(at(row, "dt"), 0.0);
    c.error = numberOr(at(row, "error"), 0.0);
    c.wall_seconds = numberOr(at(row, "wall_seconds"), 0.0);
    c.realtime_factor = numberOr(at(row, "realtime_factor"), 0.0);
    c.work = static_cast<long>(numberOr(at(row, "derivative_evaluations"), 0.0) +
                               numberOr(at(row, "linear_iterations"), 0.0));
    c.reference = at(row, "reference");
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
    for (const Choice& c : meeting) {  // cheapest first, so each engine's first is its best
      if (std::none_of(r.per_engine.begin(), r.per_engine.end(),
                       [&](const Choice& seen) { return seen.engine == c.engine; })) {
        r.per_engine.push_back(c);
      }
    }
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
