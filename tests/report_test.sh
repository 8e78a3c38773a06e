#!/usr/bin/env bash
# Builds the report from small result tables made by the real commands, and checks that every
# expected figure and the PDF exist and are not empty.
# Usage: report_test.sh SPRINGCHECK SOURCE_DIR WORK_DIR
set -euo pipefail
B=$1 SRC=$2 OUT=$3
rm -rf "$OUT"
mkdir -p "$OUT/sweep"
cd "$SRC"
$B gate --tolerances tests/data/report_tolerances.json --json "$OUT/gate.json" >/dev/null
$B sweep tests/data/report_sweep.json --out "$OUT/sweep/small_convergence.csv" --jobs 2 --repeats 1 >/dev/null 2>&1
$B stability --integrators rk4,verlet,backward-euler --stiffness 10,100 --masses 1 \
  --out "$OUT/stability" --extremes --jobs 2 >/dev/null 2>&1
for scene in chain_swing chain_hanging; do
  $B compare "scenes/matched/$scene.json" --engines mysim,mysim:symplectic-euler,bullet-deformable \
    --out "$OUT/energy/$scene" >/dev/null
done
for scene in cloth_hanging cloth_on_sphere; do
  $B compare "scenes/matched/$scene.json" --engines mysim,bullet-deformable --out "$OUT/suite/$scene" >/dev/null
done
$B report --results "$OUT" --out "$OUT/report"
missing=0
for figure in 01_summary 02_speed_accuracy 03_convergence 04_stability_map 05_energy_drift 06_drape 07_sag_penetration; do
  if [ ! -s "$OUT/report/$figure.png" ]; then echo "missing or empty: $figure.png"; missing=1; fi
done
[ -s "$OUT/report/report.pdf" ] || { echo "missing or empty: report.pdf"; missing=1; }
pages=$(grep -c "/Type /Page\b" "$OUT/report/report.pdf" || true)
[ "$pages" -eq 7 ] || { echo "report.pdf has $pages pages, expected 7"; missing=1; }
exit $missing
