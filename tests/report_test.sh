#!/usr/bin/env bash
# Builds the report from small result tables made by the real commands, with an external engine
# (examples/external's pysim) and a user's own scene among them, and checks that every page the
# manifest calls for exists, one PNG per PDF page, stamped; then that a results folder missing
# most inputs still gives a report, whose last page names the command for each missing input.
# Usage: report_test.sh SPRINGCHECK SOURCE_DIR WORK_DIR
set -euo pipefail
B=$1 SRC=$2 OUT=$3
rm -rf "$OUT"
mkdir -p "$OUT/sweep" "$OUT/recommend"
cd "$SRC"
fail() { echo "FAIL: $*"; exit 1; }
E=examples/external/engines.json
# The user's scene: a small cloth of their own, outside scenes/.
python3 - "$OUT/user_cloth.json" <<'PY'
import json, sys
scene = json.load(open("scenes/matched/cloth_hanging.json"))
scene["name"] = "user_cloth"
scene["system"]["rows"] = scene["system"]["cols"] = 6
scene["integrator"]["duration"] = 1.0
json.dump(scene, open(sys.argv[1], "w"))
PY
$B gate --tolerances tests/data/report_tolerances.json --json "$OUT/gate.json" >/dev/null
$B sweep tests/data/report_sweep.json --out "$OUT/sweep/small_convergence.csv" --jobs 2 --repeats 1 >/dev/null 2>&1
$B recommend "$OUT/sweep/small_convergence.csv" --max-error 1e-3 --json "$OUT/recommend/small_convergence.json" \
  >/dev/null || [ $? -eq 1 ]
$B stability --integrators rk4,verlet,backward-euler --stiffness 10,100 --masses 1 \
  --out "$OUT/stability" --extremes --jobs 2 >/dev/null 2>&1
$B stability --scene scenes/matched/chain_hanging.json --engines mysim:symplectic-euler,bullet-deformable \
  --stiffness-scales 0.2,2 --mass-ratios 1,100 --out "$OUT/stability" --jobs 2 >/dev/null 2>&1
for scene in chain_swing chain_hanging; do
  $B compare "scenes/matched/$scene.json" --engines mysim,mysim:symplectic-euler,bullet-deformable,pysim \
    --engines-file $E --out "$OUT/energy/$scene" >/dev/null
done
for scene in scenes/matched/cloth_on_sphere.json "$OUT/user_cloth.json"; do
  name=$(basename "$scene" .json)
  $B compare "$scene" --engines mysim,bullet-deformable,pysim --engines-file $E --out "$OUT/suite/$name" >/dev/null
done
$B refine scenes/material/cantilever_strip.json --resolutions 2,4,8 --engines mysim,pysim --engines-file $E \
  --out "$OUT/refine" >/dev/null 2>&1 || [ $? -eq 3 ]  # pysim blows up at the scene's 2 ms: said, not fatal
# The main job's stage times, as scripts/run-suite.sh writes them: the last page draws them.
cat > "$OUT/timings.json" <<'JSON'
{"stages": [{"name": "suite", "seconds": 41.5}, {"name": "sweep solver_families", "seconds": 170.2},
            {"name": "refine", "seconds": 60.0}],
 "total_seconds": 280.0, "machine": {"cores": 2, "stream_triad_bytes_per_second": 9.5e9, "cpu": "x"}}
JSON
$B report --results "$OUT" --out "$OUT/report" || fail "springcheck report failed"

# Every page the inputs call for, by name; pysim and the user's scene among them.
for page in dashboard speed_accuracy_small_convergence convergence_small_convergence stability_oscillator \
            stability_chain_hanging energy_energy_chain_swing energy_energy_chain_hanging \
            drape_suite_cloth_on_sphere drape_suite_user_cloth sag_1 penetration_1 refine_cantilever_strip \
            timings; do
  ls "$OUT/report/"[0-9][0-9]_"$page.png" >/dev/null 2>&1 || fail "no page $page"
done
for png in "$OUT"/report/*.png; do [ -s "$png" ] || fail "empty $png"; done
# Every input but the benchmarks (minutes, not part of the main job) exists: the missing-inputs
# page names only what makes the performance page.
python3 - "$OUT/report/manifest.json" <<'PYEOF' || fail "missing inputs other than the benchmarks"
import json, sys
missing = json.load(open(sys.argv[1]))["missing"]
assert [m["input"].endswith("bench/bench.json") for m in missing] == [True], missing
PYEOF
pngs=$(ls "$OUT"/report/*.png | wc -l)
pages=$(grep -c "/Type /Page\b" "$OUT/report/report.pdf" || true)
[ "$pages" -eq "$pngs" ] || fail "report.pdf has $pages pages, $pngs PNGs"
grep -q '"pysim"' "$OUT/report/manifest.json" || fail "the manifest does not list the external engine"
grep -q '"user_cloth"' "$OUT/report/manifest.json" || fail "the manifest does not list the user's scene"
grep -q '"commit"' "$OUT/report/manifest.json" || fail "the manifest has no stamp"
echo "report: $pages pages, each page present"

# Every limit a page drew has the evidence for it (tests/report_claims_check.py), and the check
# refuses one that has not: a limit from three resolutions with no expected order to hold it to.
python3 tests/report_claims_check.py "$OUT/report/claims.json" || fail "a page drew a limit without evidence"
cat > "$OUT/unevidenced_claims.json" <<'JSON'
[{"page": "refine_flex", "kind": "limit", "engine": "mysim", "quantity": "tip_drop",
  "resolutions": "4 8 16", "observed_order": "0.88", "expected_order": "", "verdict": "converged"}]
JSON
if python3 tests/report_claims_check.py "$OUT/unevidenced_claims.json" >/dev/null; then
  fail "the claims check passed a limit from three resolutions with no expected order"
fi

# A folder with a single comparison: the report still comes, and says what makes the rest.
mkdir -p "$OUT/partial/suite"
cp -r "$OUT/suite/user_cloth" "$OUT/partial/suite/"
$B report --results "$OUT/partial" --out "$OUT/partial/report" 2>"$OUT/partial/stderr" \
  || { cat "$OUT/partial/stderr"; fail "report failed on a partial results folder"; }
grep -q "Traceback" "$OUT/partial/stderr" && fail "a Python traceback"
ls "$OUT"/partial/report/*_missing_inputs.png >/dev/null 2>&1 || fail "no page of missing inputs"
for command in "springcheck gate --json" "springcheck sweep" "springcheck stability --extremes" "springcheck compare"; do
  grep -qF "$command" "$OUT/partial/report/manifest.json" || fail "the missing inputs do not name '$command'"
done
echo "partial results: the report names the commands for the missing inputs"
