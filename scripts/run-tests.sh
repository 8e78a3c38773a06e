#!/usr/bin/env bash
# The whole test suite, twice: a Release build, then every test again in a build with
# AddressSanitizer and UndefinedBehaviorSanitizer (the debug preset, -O1 so it runs in minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default
ctest --preset default -j "$(nproc)"
scripts/setup.sh debug
ctest --preset debug -j "$(nproc)"
