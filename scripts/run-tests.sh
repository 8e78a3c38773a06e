#!/usr/bin/env bash
# The whole test suite, twice: a Release build and every test, then every test again in a build
# with AddressSanitizer and UndefinedBehaviorSanitizer (the debug preset, -O1 so it runs in
# minutes), except those labelled "tooling" (tests/cli_tests.cmake: their time is Python,
# matplotlib, Slurm or a nested CMake build, not our C++) and "slow" (whole runs of every shipped
# scene in every engine, the full gate, the killed-process test: 16 of the sanitizer pass's 29
# CPU-minutes; the sanitizers run every scene's opening steps in every engine instead) and
# "releaseonly" (quick in Release, ten times slower under the sanitizers: the large-step cloth's
# 12 s runs and the other cantilever's, the trade answer on two unseen cantilevers, the hinge
# strip settled in every family, the contact landings at 1/60 s, the cloth resting on the sphere
# in backward Euler, the ablations of the cantilever, XPBD's warm start, the oscillator's orders,
# the hanging drape specimen, the error budget's orders; their code runs there in shorter tests,
# each file saying which), which the Release pass has run.
#
# The sanitizer build runs beside the Release tests at the lowest priority (nice 19): the Release
# pass is held by the main job's test, whose single-threaded stretches leave a core idle, and the
# build takes only what the tests leave (docs/ci.md, "springcheck's own CI").
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default

build_log=$(mktemp)
# Its own process group (job control on for this one job), so a failed Release pass stops all of
# it; not its own session (setsid), whose autogroup would share the CPU with the tests as equals.
set -m
nice -n 19 scripts/setup.sh debug > "$build_log" 2>&1 &
build_group=$!
set +m
trap 'kill -- -"$build_group" 2>/dev/null || true; rm -f "$build_log"' EXIT

ctest --preset default -j "$(nproc)"
if ! wait "$build_group"; then
  cat "$build_log"
  echo "FAIL: the sanitizer build (scripts/setup.sh debug) failed, its log above" >&2
  exit 1
fi
trap 'rm -f "$build_log"' EXIT
ctest --preset debug -j "$(nproc)" --label-exclude 'tooling|slow|releaseonly'
