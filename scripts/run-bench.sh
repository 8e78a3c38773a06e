#!/usr/bin/env bash
# Benchmarks: mysim against the hardware and against Bullet, side by side in one run (medians of
# 3 repetitions), plus a peak-memory probe. Writes out/bench/ and prints the table that
# docs/performance.md keeps. Takes about 10 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default springcheck springcheck_bench
OUT=${SPRINGCHECK_OUT:-out}/bench
mkdir -p "$OUT"
build/release/bench/springcheck_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_min_time=0.5 --benchmark_out="$OUT/bench.json" --benchmark_out_format=json
build/release/compare/springcheck run bench/cloth256_rk4.json --out "$OUT/memory" >/dev/null
build/release/compare/springcheck run scenes/seed/circle.json --out "$OUT/memory_baseline" >/dev/null
python3 bench/summarize.py "$OUT/bench.json" "$OUT/memory/summary.json" \
  "$OUT/memory_baseline/summary.json" "$OUT/summary.csv"
