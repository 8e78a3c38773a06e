#!/usr/bin/env bash
# Where a benchmark's figures came from: prints the machine's name, CPU, cores, memory and STREAM
# triad bandwidth, the date, the commit and the command (its arguments), for the machine.txt
# beside the figures in bench/results/MACHINE/, so a later run compares ratios, not absolute times.
# Usage: scripts/machine-info.sh MACHINE COMMAND (the benchmark binary must be built).
set -euo pipefail
cd "$(dirname "$0")/.."
triad=$(build/release/bench/springcheck_bench --benchmark_filter='^BM_StreamTriad/' \
  --benchmark_format=json 2>/dev/null |
  python3 -c 'import json, sys
b = json.load(sys.stdin)["benchmarks"][0]
print("%.1f GB/s" % (b["bytes_per_second"] / 1e9))')
echo "machine: $1"
grep -m1 "model name" /proc/cpuinfo | sed 's/^model name\s*: /cpu: /'
echo "cores: $(nproc)"
echo "memory: $(awk '/MemTotal/ { printf "%.1f GiB", $2 / 1048576 }' /proc/meminfo)"
echo "stream triad: $triad (2 threads, bench/bandwidth_bench.cpp)"
echo "date: $(date -u +%Y-%m-%d)"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo "command: $2"
