#!/usr/bin/env bash
# The main job: set up, build, run the default comparison suite and write the report.
#   out/suite/      every scene in every engine that takes it, the example external engine
#                   (examples/external/) included (comparison tables, runs)
#   out/gate.json   the tolerance gates
#   out/energy/     energy drift of every integrator and engine, undamped and damped
#   out/sweep/      speed/accuracy and convergence sweeps
#   out/stability/  largest stable steps against theory (the oscillator, and every engine on
#                   the chain and the cloth), and the extremes
#   out/recommend/  the cheapest engine, integrator and step under 1 mm of error, per sweep, and
#                   each solver family's cheapest under 1 mm and 1 cm
#   out/report/     report.pdf and one PNG per figure
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default springcheck
B=build/release/cli/springcheck
OUT=${SPRINGCHECK_OUT:-out}
start=$(date +%s)

# Every engine of the registry, the example external engine (examples/external/) included.
E=examples/external/engines.json
# Exit 3: some engine blew up on some scene (explicit ones at the material scenes' 2 ms step):
# a result the report shows, not a failure of the job.
$B suite scenes --out "$OUT/suite" --engines-file "$E" || [ $? -eq 3 ]
gate_status=0
$B gate --json "$OUT/gate.json" || gate_status=$?

# Every integrator on an undamped and a damped scene. Forward Euler blows up on the undamped
# chain (exit 3): that is a result, recorded and drawn, not a failure of the job.
# (--engines all: mysim once per integrator of the catalogue, then every other engine.)
for scene in chain_swing chain_hanging; do
  $B compare "scenes/matched/$scene.json" --out "$OUT/energy/$scene" --engines all \
    --engines-file "$E" >/dev/null || [ $? -eq 3 ]
done

for spec in compare/sweeps/*.json; do
  $B sweep "$spec" --fresh --out "$OUT/sweep/$(basename "$spec" .json).csv"
done
# The answer users want, for the report's first page: the cheapest choice under 1 mm of error on
# each sweep measured against one converged reference (exit 1 when nothing qualifies: a result).
mkdir -p "$OUT/recommend"
for table in "$OUT"/sweep/chain_convergence.csv "$OUT"/sweep/cloth_speed_accuracy.csv \
    "$OUT"/sweep/solver_families.csv; do
  $B recommend "$table" --max-error 1e-3 --json "$OUT/recommend/$(basename "$table" .csv).json" \
    >/dev/null || [ $? -eq 1 ]
done
# Which solver family at 1 cm too (the report's solver-family page sets the two bounds side by side).
$B recommend "$OUT"/sweep/solver_families.csv --max-error 1e-2 \
  --json "$OUT/recommend/solver_families_1cm.json" >/dev/null || [ $? -eq 1 ]
$B stability --out "$OUT/stability" --extremes >/dev/null
# Every engine's stability map on the chain and the cloth, with the w_max theory lines (the
# cloth over two mass ratios to stay inside the job's time; --mass-ratios 1,100,1e4 for all).
$B stability --scene scenes/matched/chain_swing.json --out "$OUT/stability" >/dev/null
$B stability --scene scenes/matched/cloth_hanging.json --mass-ratios 1,1e4 --out "$OUT/stability" >/dev/null
# The families that claim unconditional stability, on the cloth up to h w_max = 3000 (1/60 s and
# beyond on its stiffest springs): where each stops having it (backward Euler beside them).
$B stability --scene scenes/matched/cloth_hanging.json --name cloth_hanging_large_steps \
  --engines mysim:xpbd,mysim:local-global,mysim:vbd,mysim:backward-euler --stiffness-scales 1,100 \
  --mass-ratios 1,1e4 --max-h-omega 3000 --out "$OUT/stability" >/dev/null
# Mesh refinement: the cantilever against the elastica, the flex-spring strip, the drape test,
# the cable against the continuous catenary.
$B refine scenes/material/cantilever_strip.json scenes/material/cantilever_strip_flex.json \
  scenes/material/cusick_drape.json scenes/material/cable_catenary.json --resolutions 4,8,16 \
  --engines mysim,bullet-implicit \
  --out "$OUT/refine" >/dev/null || [ $? -eq 3 ]
$B report --results "$OUT" --out "$OUT/report"
echo "main job done in $(( $(date +%s) - start )) s; report: $OUT/report/report.pdf"
exit "$gate_status"
