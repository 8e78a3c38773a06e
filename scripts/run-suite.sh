#!/usr/bin/env bash
# The main job: set up, build, and run the default suite over scenes/. Results go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default springcheck
./build/release/compare/springcheck suite scenes --out out/suite
