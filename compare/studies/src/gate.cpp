#include "compare/studies/gate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "compare/io/text_format.h"
#include "compare/studies/comparison.h"
#include "mysim/scene_file.h"

namespace springcheck {

bool GateReport::passed() const {
  return std::all_of(results.begin(), results.end(), [](const CheckResult& r) { return r.passed; });
}

namespace {

// Why the check has no run to read: one of its engines was refused or failed.
std::optional<std::string> missingRun(const ToleranceCheck& check, const Comparison& c) {
  auto named = [&](const Comparison::Refusal& r) {
    return std::find(check.engines.begin(), check.engines.end(), r.engine) != check.engines.end();
  };
  for (const Comparison::Refusal& refusal : c.refused) {
    if (named(refusal)) return "refused: " + refusal.reason;
  }
  for (const Comparison::Refusal& failure : c.failed) {
    if (named(failure)) return "failed: " + failure.reason;
  }
  return std::nullopt;
}

const EngineMetrics* metricsOf(const Comparison& c, const std::string& engine) {
  for (const EngineMetrics& m : c.engines) {
    if (m.engine == engine) return &m;
  }
  return nullptr;
}

// r.measured from one engine's run (with the closed form's unit, and a note when the error is
// the motion left at the end); false with r.problem when the run blew up.
bool measureOne(const ToleranceCheck& check, const Comparison& c, CheckResult& r) {
  const EngineMetrics* m = metricsOf(c, check.engines[0]);
  if (m->blew_up && check.metric != "blowup") {
    r.problem = check.engines[0] + " blew up at t = " + std::to_string(m->blowup_time) + " s";
    return false;
  }
  r.measured = metricValue(*m, check.metric);
  if (check.metric == "closed_form_error" && m->closed_form) {
    r.unit = m->closed_form->unit;
  }
  if (check.metric == "closed_form_error" && m->closed_form && m->closed_form->atMotionFloor()) {
    r.note = "the run still moved " + formatNumber(*m->closed_form->motion_left, 2) +
             " m over its last tenth: an error this close to that is the motion left at the "
             "end, not the engine's accuracy (a longer run shows it)";
  }
  return true;
}

// r.measured from the pair of the check's two engines; false with r.problem when one blew up.
bool measurePair(const ToleranceCheck& check, const Comparison& c, CheckResult& r) {
  for (const std::string& engine : check.engines) {
    if (metricsOf(c, engine)->blew_up) {
      r.problem = engine + " blew up at t = " + std::to_string(metricsOf(c, engine)->blowup_time) +
                  " s";
      return false;
    }
  }
  for (const PairMetrics& p : c.pairs) {
    if ((p.a == check.engines[0] && p.b == check.engines[1]) ||
        (p.a == check.engines[1] && p.b == check.engines[0])) {
      r.measured = metricValue(p, check.metric);
    }
  }
  return true;
}

}  // namespace

CheckResult evaluateCheck(const ToleranceCheck& check, const Comparison& c) {
  CheckResult r{check, std::nullopt, false, "", "", {}, ""};
  if (const MetricInfo* info = findMetric(check.metric)) r.unit = info->unit;
  for (const std::string& engine : check.engines) {
    std::string stepper;
    for (const EngineRun& run : c.runs) {
      if (run.engine == engine) stepper = run.record.integrator;
    }
    r.steppers.push_back(stepper);
  }
  if (auto missing = missingRun(check, c)) {
    r.problem = *missing;
    return r;
  }
  if (!(check.engines.size() == 1 ? measureOne(check, c, r) : measurePair(check, c, r))) return r;
  if (!r.measured) {
    r.problem = "metric '" + check.metric + "' is not defined for this scene";
    return r;
  }
  if (!check.physical_error.empty()) {  // the metric against its closed form
    const double error = std::abs(*r.measured - check.reference);
    const bool relative = check.physical_error == "relative";
    r.note = check.metric + " " + formatNumber(*r.measured, 6) + " against the physical " +
             formatNumber(check.reference, 6) + (r.note.empty() ? "" : "; " + r.note);
    r.measured = relative ? error / std::abs(check.reference) : error;
    if (relative) r.unit = "rel";
  }
  r.passed = *r.measured <= check.bound;
  return r;
}

namespace {

// Whether a comparison holds (a run, a refusal or a failure of) every engine in `engines`.
bool covers(const Comparison& c, const std::vector<std::string>& engines) {
  for (const std::string& e : engines) {
    auto named = [&](const auto& list) {
      return std::any_of(list.begin(), list.end(), [&](const auto& x) { return x.engine == e; });
    };
    if (!named(c.runs) && !named(c.refused) && !named(c.failed)) return false;
  }
  return true;
}

}  // namespace

std::expected<GateReport, std::string> runGate(const EngineRegistry& registry,
                                               const Tolerances& tolerances,
                                               const ComparisonCache& done) {
  // Engines per scene, in order of first mention, so every run happens once.
  std::map<std::string, std::vector<std::string>> engines;
  std::vector<std::string> scenes;
  for (const ToleranceCheck& check : tolerances.checks) {
    if (!engines.count(check.sceneKey())) scenes.push_back(check.sceneKey());
    auto& list = engines[check.sceneKey()];
    for (const std::string& e : check.engines) {
      if (std::find(list.begin(), list.end(), e) == list.end()) list.push_back(e);
    }
  }
  GateReport report;
  std::map<std::string, Comparison> comparisons;
  for (const std::string& key : scenes) {
    // A variant's key is no file name, so only the scenes as written are found in `done`.
    std::error_code ec;
    const auto cached = done.find(std::filesystem::weakly_canonical(key, ec).string());
    if (cached != done.end() && covers(cached->second, engines[key])) {
      comparisons.emplace(key, cached->second);
      continue;
    }
    auto comparison = compareScene(registry, tolerances.scenes.at(key), engines[key]);
    if (!comparison) return std::unexpected(key + ": " + comparison.error());
    comparisons.emplace(key, std::move(*comparison));
  }
  for (const ToleranceCheck& check : tolerances.checks) {
    report.results.push_back(evaluateCheck(check, comparisons.at(check.sceneKey())));
  }
  return report;
}

void printGate(std::ostream& out, const GateReport& report) {
  int failed = 0;
  char line[1024];
  for (const CheckResult& r : report.results) {
    std::string engines = r.check.engines[0];
    if (r.check.engines.size() > 1) engines += " ~ " + r.check.engines[1];
    std::string scene =
        r.check.scene.substr(r.check.scene.find_last_of('/') + 1) + r.check.variantLabel();
    if (r.measured) {
      const std::string& unit = r.unit;
      std::snprintf(line, sizeof line, "%s  %-22s %-20s %-44s %11.4g <= %-11.4g %s",
                    r.passed ? "PASS" : "FAIL", scene.c_str(), r.check.metricLabel().c_str(),
                    engines.c_str(), *r.measured, r.check.bound, unit.c_str());
    } else {
      std::snprintf(line, sizeof line, "FAIL  %-22s %-20s %-44s %s", scene.c_str(),
                    r.check.metricLabel().c_str(), engines.c_str(), r.problem.c_str());
    }
    out << line << "\n      why: " << r.check.why << '\n';
    if (!r.note.empty()) out << "      note: " << r.note << '\n';
    failed += !r.passed;
  }
  out << "gate: " << report.results.size() - failed << " passed, " << failed << " failed\n";
}

}  // namespace springcheck
