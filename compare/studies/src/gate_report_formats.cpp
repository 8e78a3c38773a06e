#include "compare/studies/gate_report_formats.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "compare/io/atomic_file.h"
#include "compare/metrics/run_metrics.h"

namespace springcheck {
namespace {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // XML 1.0 allows no control characters but tab, newline and carriage return.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += ' ';
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string numberText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

std::string engines(const ToleranceCheck& check) {
  std::string out;
  for (const std::string& e : check.engines) out += (out.empty() ? "" : " ~ ") + e;
  return out;
}

std::string sceneName(const ToleranceCheck& check) {
  return std::filesystem::path(check.scene).stem().string() + check.variantLabel();
}

// Why a check failed, in one line: what was measured against what, or why nothing was.
std::string failureMessage(const CheckResult& r) {
  if (!r.measured) return "no measurement: " + r.problem;
  return "measured " + numberText(*r.measured) + " > bound " + numberText(r.check.bound);
}

}  // namespace

std::string checkName(const ToleranceCheck& check) {
  return sceneName(check) + ": " + check.metricLabel() + " of " + engines(check) +
         " <= " + numberText(check.bound);
}

void writeJunit(std::ostream& out, const GateReport& report, const std::string& tolerances) {
  const auto failures = std::count_if(report.results.begin(), report.results.end(),
                                      [](const CheckResult& r) { return !r.passed; });
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"springcheck gate\" tests=\"" << report.results.size()
      << "\" failures=\"" << failures << "\">\n"
      << "  <testsuite name=\"" << xmlEscaped(tolerances) << "\" tests=\"" << report.results.size()
      << "\" failures=\"" << failures << "\">\n";
  for (const CheckResult& r : report.results) {
    out << "    <testcase classname=\"springcheck.gate." << xmlEscaped(sceneName(r.check))
        << "\" name=\"" << xmlEscaped(checkName(r.check)) << "\"";
    if (r.passed) {
      const std::string measured = r.measured ? numberText(*r.measured) : "-";
      out << ">\n      <system-out>"
          << xmlEscaped("measured " + measured + " <= bound " + numberText(r.check.bound) +
                        "; why this bound: " + r.check.why +
                        (r.note.empty() ? "" : "; note: " + r.note))
          << "</system-out>\n    </testcase>\n";
      continue;
    }
    out << ">\n      <failure message=\"" << xmlEscaped(failureMessage(r)) << "\" type=\""
        << (r.measured ? "bound" : "no-measurement") << "\">"
        << xmlEscaped(failureMessage(r) + "\nscene: " + r.check.scene +
                      "\nengines: " + engines(r.check) + "\nmetric: " + r.check.metricLabel() +
                      "\nwhy this bound: " + r.check.why)
        << "</failure>\n    </testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
}

void writeGateMarkdown(std::ostream& out, const GateReport& report, const std::string& tolerances) {
  std::vector<const CheckResult*> rows;
  for (const CheckResult& r : report.results) rows.push_back(&r);
  std::stable_partition(rows.begin(), rows.end(), [](const CheckResult* r) { return !r->passed; });
  const auto failed = std::count_if(rows.begin(), rows.end(), [](auto* r) { return !r->passed; });
  out << "**springcheck gate** (`" << tolerances << "`): " << rows.size() - failed << " passed, "
      << failed << " failed\n\n"
      << "| | scene | metric | engines | measured | bound |\n| --- | --- | --- | --- | --- | --- "
         "|\n";
  auto cell = [](std::string text) {  // a | would end the cell
    for (std::size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2) {
      text.replace(at, 1, "\\|");
    }
    return text;
  };
  for (const CheckResult* r : rows) {
    out << "| " << (r->passed ? "pass" : "**FAIL**") << " | " << cell(sceneName(r->check)) << " | "
        << cell(r->check.metricLabel()) << " | " << cell(engines(r->check)) << " | "
        << (r->measured ? numberText(*r->measured) : cell(r->problem)) << " | "
        << numberText(r->check.bound) << " |\n";
  }
}

void writeGateJson(std::ostream& out, const GateReport& report, const std::string& tolerances) {
  nlohmann::json results = nlohmann::json::array();
  for (const CheckResult& r : report.results) {
    results.push_back({{"scene", r.check.scene},
                       {"engines", r.check.engines},
                       {"metric", r.check.metric},
                       {"resolution", r.check.resolution ? nlohmann::json(*r.check.resolution)
                                                         : nlohmann::json()},
                       {"dt", r.check.dt ? nlohmann::json(*r.check.dt) : nlohmann::json()},
                       {"physical_error", r.check.physical_error},
                       {"reference", r.check.physical_error.empty()
                                         ? nlohmann::json()
                                         : nlohmann::json(r.check.reference)},
                       {"bound", r.check.bound},
                       {"why", r.check.why},
                       {"known_bias", r.check.known_bias.empty() ? nlohmann::json()
                                                                 : nlohmann::json(r.check.known_bias)},
                       {"passed", r.passed},
                       {"problem", r.problem},
                       {"note", r.note},
                       {"steppers", r.steppers},
                       {"unit", r.unit},
                       {"measured", r.measured ? nlohmann::json(*r.measured) : nlohmann::json()}});
  }
  const nlohmann::json all = {{"tolerances", tolerances}, {"checks", results}};
  out << jsonText(all, 2) << '\n';
}

}  // namespace springcheck
