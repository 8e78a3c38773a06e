#!/usr/bin/env bash
# Benchmarks: mysim against the hardware and against Bullet, side by side in one run (medians of
# 3 repetitions), a peak-memory probe, and speed at equal accuracy (each engine's cheapest
# setting under 1 mm of error on the hanging cloth and the cloth on the sphere, springcheck
# recommend). Writes out/bench/, prints the table that docs/performance.md keeps, and copies it
# to bench/results/MACHINE/ (MACHINE: $SPRINGCHECK_MACHINE, else host name and core count), one
# folder per machine so every figure says where it came from. About 26 minutes on 2 cores (the
# solver families' equal-accuracy sweep included).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default springcheck springcheck_bench
OUT=${SPRINGCHECK_OUT:-out}/bench
mkdir -p "$OUT"
build/release/bench/springcheck_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_min_time=0.5 --benchmark_out="$OUT/bench.json" --benchmark_out_format=json
build/release/cli/springcheck run bench/cloth256_rk4.json --out "$OUT/memory" >/dev/null
build/release/cli/springcheck run scenes/seed/circle.json --out "$OUT/memory_baseline" >/dev/null
for scene in cloth_hanging cloth_on_sphere; do
  build/release/cli/springcheck recommend "scenes/matched/$scene.json" --max-error 1e-3 --repeats 3 \
    --table "$OUT/equal_accuracy_$scene.csv" --json "$OUT/equal_accuracy_$scene.json" >/dev/null || [ $? -eq 1 ]
done
# The solver families at equal accuracy on finer cloths (docs/performance.md, "Solver families at
# large steps"): 32 x 32 and 64 x 64, one case at a time; about 6 minutes on 2 cores.
build/release/cli/springcheck sweep bench/solver_families_large.json --fresh --jobs 1 \
  --out "$OUT/solver_families_large.csv" >/dev/null
for bound in 1e-3 1e-2; do
  build/release/cli/springcheck recommend "$OUT/solver_families_large.csv" --max-error "$bound" \
    --json "$OUT/solver_families_large_$bound.json" >/dev/null || [ $? -eq 1 ]
done
python3 bench/summarize.py "$OUT/bench.json" "$OUT/memory/summary.json" \
  "$OUT/memory_baseline/summary.json" "$OUT/summary.csv" \
  "$OUT/equal_accuracy_cloth_hanging.json" "$OUT/equal_accuracy_cloth_on_sphere.json"
machine=${SPRINGCHECK_MACHINE:-$(hostname -s)-$(nproc)cores}
mkdir -p "bench/results/$machine"
cp "$OUT/summary.csv" "bench/results/$machine/summary.csv"
scripts/machine-info.sh "$machine" scripts/run-bench.sh >"bench/results/$machine/machine.txt"
echo "results: bench/results/$machine/"
