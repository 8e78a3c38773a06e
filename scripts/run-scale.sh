#!/usr/bin/env bash
# The solver families at scale (issue 36; docs/performance.md "Scale"): cost per step and peak
# memory of every engine bench/scale_study.json lists on the benchmark cloth at 64, 128, 256 and
# 512 cells a side (262 144 nodes), one thread, 1/60 s, each run a process of its own; the growth
# exponent of each. Writes out/bench/scale/ and copies the tables to bench/results/MACHINE/ with
# the machine's STREAM figure. About 30 minutes on one core (the defaults at 512 cells are most of
# it). --equal-error: bench/equal_error_study.json instead, every family solving each step to the
# same relative error (1e-3) at 32 to 256 cells (docs/performance.md "Speed at equal solver
# error"), into out/bench/equal_error/ and equal_error*.csv. Other arguments go to
# bench/scale_study.py (--resolutions 64,128 --steps 2 for a quick look).
set -euo pipefail
cd "$(dirname "$0")/.."
command="scripts/run-scale.sh $*"
study=scale
if [[ "${1:-}" == --equal-error ]]; then
  study=equal_error
  shift
fi
scripts/setup.sh default springcheck springcheck_bench
OUT=${SPRINGCHECK_OUT:-out}/bench/$study
python3 bench/scale_study.py build/release/cli/springcheck "bench/${study}_study.json" "$OUT" "$@"
machine=${SPRINGCHECK_MACHINE:-$(hostname -s)-$(nproc)cores}
mkdir -p "bench/results/$machine"
cp "$OUT/scale.csv" "bench/results/$machine/$study.csv"
cp "$OUT/scale_fit.csv" "bench/results/$machine/${study}_fit.csv"
scripts/machine-info.sh "$machine" "$command" >"bench/results/$machine/${study}_machine.txt"
echo "results: bench/results/$machine/$study.csv, ${study}_fit.csv"
