#!/usr/bin/env bash
# The whole test suite, twice: a Release build and every test, then every test again in a build
# with AddressSanitizer and UndefinedBehaviorSanitizer (the debug preset, -O1 so it runs in
# minutes), except those labelled "tooling" (tests/CMakeLists.txt: their time is Python,
# matplotlib, Slurm or a nested CMake build, not our C++) and "slow" (whole runs of every shipped
# scene in every engine, the full gate, the killed-process test: 16 of the sanitizer pass's 29
# CPU-minutes; the sanitizers run every scene's opening steps in every engine instead) and
# "releaseonly" (quick in Release, ten times slower under the sanitizers: the large-step cloth's
# 12 s runs and the other cantilever's, the trade answer on two unseen cantilevers, the hinge
# strip settled in every family, the contact landings at 1/60 s; their code runs there in
# shorter tests, each file saying which), which the Release pass has run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default
ctest --preset default -j "$(nproc)"
scripts/setup.sh debug
ctest --preset debug -j "$(nproc)" --label-exclude 'tooling|slow|releaseonly'
