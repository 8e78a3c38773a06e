#!/usr/bin/env bash
# The whole test suite: set up, build, run every test (Release), then the scene-validation tests
# again under AddressSanitizer and UndefinedBehaviorSanitizer (Debug preset).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default
ctest --preset default -j "$(nproc)"
scripts/setup.sh debug springcheck scene_validation_tests
ctest --preset debug -L validation -j "$(nproc)"
