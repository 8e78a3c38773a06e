#!/usr/bin/env bash
# The main job whole (scripts/main-job.sh) on the test build: it must end with exit 0 (every gate
# check held, the report written), and each stage's work, in runs and steps, must stay within
# 20 % of its record (scripts/main-job-work.json; scripts/check-main-job-work.py): the job's
# budget held by counts, which no machine's speed or load changes. Then every number
# docs/findings.md quotes from the job's tables, and from the few commands outside it
# (scripts/findings-commands.sh, about a minute), is held to them (scripts/check-findings.py).
# Usage: main_job_work_test.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -uo pipefail
src=$1 build=$2 out=$3
rm -rf "$out" "$out.log"
SPRINGCHECK_BUILD="$build" SPRINGCHECK_OUT="$out" "$src/scripts/main-job.sh" > "$out.log" 2>&1
rc=$?
if [ "$rc" -ne 0 ]; then
  # The tolerance gate's failed checks with their reasons (this test is the gate in a build with
  # matplotlib: tests/cli_tests.cmake), then the end of the log.
  grep -A2 '^FAIL ' "$out.log" | head -60
  tail -40 "$out.log"
  echo "FAIL: the main job exited $rc (log: $out.log)"
  exit 1
fi
grep '^stage ' "$out.log"
[ -s "$out/report/report.pdf" ] || { echo "FAIL: no report at $out/report/report.pdf"; exit 1; }
python3 "$src/scripts/check-main-job-work.py" "$out/timings.json" "$src/scripts/main-job-work.json" || exit 1
"$src/scripts/findings-commands.sh" "$build" "$out" || { echo "FAIL: scripts/findings-commands.sh"; exit 1; }
python3 "$src/scripts/check-findings.py" "$src/docs/findings.md" "$out" || {
  echo "FAIL: docs/findings.md quotes a number its table no longer says (above)"; exit 1; }
