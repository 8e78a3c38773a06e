#!/usr/bin/env bash
# A failing gate writes JUnit XML that CI systems read: one test case per check, the failing one
# with its measured value, its bound and the reason for the bound; and a markdown table with the
# failure first. The gate itself exits 1.
# Usage: gate_junit_test.sh SPRINGCHECK PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
cat > "$work/tolerances.json" <<JSON
{"scene_root": "$src", "checks": [
  {"scene": "scenes/seed/circle.json", "engines": ["mysim"], "metric": "closed_form_error", "bound": 1e-5,
   "why": "RK4 phase error t h^4 / 120 & more <here>"},
  {"scene": "scenes/seed/circle.json", "engines": ["mysim"], "metric": "closed_form_error", "bound": 1e-12,
   "why": "deliberately impossible: the failing check"}
]}
JSON
status=0
"$exe" gate --tolerances "$work/tolerances.json" --junit "$work/gate.xml" --markdown "$work/gate.md" \
  >/dev/null || status=$?
[ "$status" -eq 1 ] || { echo "a failing gate must exit 1, got $status"; exit 1; }
"$python" - "$work/gate.xml" "$work/gate.md" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()  # raises on malformed XML (the & and < of the reason)
cases = root.findall(".//testcase")
assert root.get("tests") == "2" and root.get("failures") == "1", root.attrib
assert len(cases) == 2, len(cases)
failed = [c for c in cases if c.find("failure") is not None]
assert len(failed) == 1, "exactly one failure"
failure = failed[0].find("failure")
message = failure.get("message")
assert message.startswith("measured ") and "> bound 1e-12" in message, message
measured = float(message.split()[1])
assert 1e-12 < measured < 1e-5, measured  # RK4's real error on the circle
assert "deliberately impossible" in failure.text, failure.text
assert failed[0].get("name") == "circle: closed_form_error of mysim <= 1e-12", failed[0].get("name")
assert "& more <here>" in cases[0].find("system-out").text
md = open(sys.argv[2]).read().splitlines()
assert md[0].startswith("**springcheck gate**") and "1 passed, 1 failed" in md[0], md[0]
assert md[4].startswith("| **FAIL** | circle | closed_form_error | mysim |"), md[4]
print("junit and markdown carry the failing check:", message)
PY
