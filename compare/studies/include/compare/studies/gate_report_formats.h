#pragma once
// A gate's results in the forms CI systems read: JUnit XML (one test case per check) and a
// markdown table for a pull-request comment.
#include <ostream>
#include <string>

#include "compare/studies/gate.h"

namespace springcheck {

// The check's name: "SCENE: METRIC of ENGINE[ ~ ENGINE] <= BOUND" (two checks of one metric
// differ in their bound).
std::string checkName(const ToleranceCheck& check);

// <testsuites><testsuite name=...> with one <testcase classname="springcheck.gate.SCENE"
// name=CHECK> per check; a failed check carries <failure message="measured M > bound B">
// with the reason for the bound, a check with nothing measured its problem.
void writeJunit(std::ostream& out, const GateReport& report, const std::string& tolerances);

// "| | scene | metric | engines | measured | bound |" rows, failures first, and a one-line total.
void writeGateMarkdown(std::ostream& out, const GateReport& report, const std::string& tolerances);
// {"tolerances": FILE, "checks": [{scene, engines, metric, bound, why, passed, problem, measured}]}
void writeGateJson(std::ostream& out, const GateReport& report, const std::string& tolerances);

}  // namespace springcheck
