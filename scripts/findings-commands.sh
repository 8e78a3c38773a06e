#!/usr/bin/env bash
# The commands behind the numbers docs/findings.md quotes from outside the main job, each writing
# its tables under OUT/findings/NAME/, where scripts/check-findings.py finds them (the main job's
# test runs this after the main job, then the check). Each is small: about a minute in all on 2
# cores. Usage: findings-commands.sh BUILD_DIR OUT
set -euo pipefail
cd "$(dirname "$0")/.."
B=$1/cli/springcheck
F=$2/findings
mkdir -p "$F"
# Section 1: backward Euler beside Bullet's two deformable solvers on the hanging cloth.
$B compare scenes/matched/cloth_hanging.json --engines mysim:backward-euler,bullet-deformable,bullet-implicit \
  --out "$F/cloth_hanging_backward_euler" >/dev/null
# Section 3: the swinging chain over its whole 4 s against a converged run.
$B sweep scripts/findings/chain_swing_4s.json --fresh --jobs 1 --out "$F/chain_swing_4s.csv" >/dev/null 2>&1
# Section 7: the seed cloth run to rest (40 s instead of the scene's 5).
$B compare scenes/seed/cloth.json --engines mysim,bullet-deformable,bullet-implicit --duration 40 \
  --out "$F/seed_cloth_at_rest" >/dev/null
# Section 12: the cable at finer links.
$B refine scenes/material/cable_catenary.json --resolutions 10,20,40 --engines mysim \
  --out "$F/cable_10_20_40" >/dev/null 2>&1
