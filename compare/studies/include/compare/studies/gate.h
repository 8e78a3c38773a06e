#pragma once
#include <expected>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/studies/comparison.h"
#include "compare/studies/tolerances.h"

namespace springcheck {

struct CheckResult {
  ToleranceCheck check;
  std::optional<double> measured;
  bool passed = false;
  std::string problem;  // why there is no measurement (refused, blew up, metric undefined)
  std::string note;     // what the number does not say (a closed form at the motion left)
  // What stepped each engine of the check, in its order ("rk4" for "mysim" on a scene written
  // for RK4): "mysim" alone names the scene's integrator, which differs from scene to scene.
  std::vector<std::string> steppers;
  std::string unit;  // the measured value's ("m", "rel", "J", "1/0"); a closed form's its own
};

struct GateReport {
  std::vector<CheckResult> results;
  bool passed() const;
};

// One check against the comparison of its scene (which ran every engine the check names).
CheckResult evaluateCheck(const ToleranceCheck& check, const Comparison& comparison);

// Comparisons already run, by scene file (as std::filesystem::weakly_canonical names it).
using ComparisonCache = std::map<std::string, Comparison>;

// Runs each scene once in every engine its checks name, then checks every bound. A scene in
// `done` that ran every engine its checks need is not run again. Fails only when a run is invalid
// (a limit every run is held to).
[[nodiscard]] std::expected<GateReport, std::string> runGate(const EngineRegistry& registry,
                                                             const Tolerances& tolerances,
                                                             const ComparisonCache& done = {});
void printGate(std::ostream& out, const GateReport& report);

}  // namespace springcheck
