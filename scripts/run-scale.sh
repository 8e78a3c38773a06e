#!/usr/bin/env bash
# The solver families at scale (issue 36; docs/performance.md "Scale"): cost per step and peak
# memory of every engine bench/scale_study.json lists on the benchmark cloth at 64, 128, 256 and
# 512 cells a side (262 144 nodes), one thread, 1/60 s, each run a process of its own; the growth
# exponent of each. Writes out/bench/scale/ and copies the tables to bench/results/MACHINE/ with
# the machine's STREAM figure. About 30 minutes on one core (the defaults at 512 cells are most of
# it); extra arguments go to bench/scale_study.py (--resolutions 64,128 --steps 2 for a quick look).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default springcheck springcheck_bench
OUT=${SPRINGCHECK_OUT:-out}/bench/scale
python3 bench/scale_study.py build/release/cli/springcheck bench/scale_study.json "$OUT" "$@"
machine=${SPRINGCHECK_MACHINE:-$(hostname -s)-$(nproc)cores}
mkdir -p "bench/results/$machine"
cp "$OUT/scale.csv" "$OUT/scale_fit.csv" "bench/results/$machine/"
scripts/machine-info.sh "$machine" "scripts/run-scale.sh $*" >"bench/results/$machine/scale_machine.txt"
echo "results: bench/results/$machine/scale.csv, scale_fit.csv"
