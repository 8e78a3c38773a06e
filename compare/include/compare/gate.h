#pragma once
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "compare/tolerances.h"

namespace springcheck {

struct CheckResult {
  ToleranceCheck check;
  std::optional<double> measured;
  bool passed = false;
  std::string problem;  // why there is no measurement (refused, blew up, metric undefined)
};

struct GateReport {
  std::vector<CheckResult> results;
  bool passed() const;
};

// Runs each scene once in every engine its checks name, then checks every bound.
GateReport runGate(const EngineRegistry& registry, const Tolerances& tolerances);
void printGate(std::ostream& out, const GateReport& report);

}  // namespace springcheck
