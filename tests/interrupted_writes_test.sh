#!/usr/bin/env bash
# A stability search, a compare and a sweep killed at random moments (SIGKILL, mid-run or
# mid-write) leave their result file either as it was (the previous complete file) or as the new
# complete one, never a partial one. Each is killed 8 times at delays spread over its run.
# Usage: interrupted_writes_test.sh SPRINGCHECK PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work"

# Fingerprint of a result file; fails if it is not whole.
check() {  # kind file
  "$python" - "$1" "$2" <<'PY'
import csv, hashlib, json, sys
kind, path = sys.argv[1], sys.argv[2]
data = open(path, "rb").read()
if kind == "json":
    json.loads(data)  # raises on a partial file
else:
    rows = list(csv.reader(data.decode().splitlines()))
    assert rows and data.endswith(b"\n"), "cut short"
    assert all(len(r) == len(rows[0]) for r in rows), "a row cut short"
print(hashlib.sha1(data).hexdigest()[:12])
PY
}

# Two symplectic integrators: their bisections are short (RK4's took 3x as long and made this the
# slowest test of the sanitizer build), and the table is still several cases written at once.
stability=(stability --out "$work/stability" --integrators verlet,symplectic-euler --stiffness 10,1000 --masses 1 --jobs 1)
compare=(compare "$src/scenes/matched/chain_hanging.json" --engines mysim,mysim:verlet --out "$work/compare")
sweep_spec="$work/sweep.json"
cat > "$sweep_spec" <<JSON
{"scenes": ["$src/scenes/seed/circle.json"], "integrators": ["euler", "rk4", "trapezoidal"],
 "dt": [0.1, 0.05, 0.025, 0.0125], "duration": 3.0, "sample_interval": 0.1, "reference": "closed_form"}
JSON
sweep=(sweep "$sweep_spec" --out "$work/sweep.csv" --fresh --jobs 1 --repeats 1)

for job in stability compare sweep; do
  case $job in
    stability) cmd=("${stability[@]}"); result="$work/stability/stability.csv"; kind=csv ;;
    compare) cmd=("${compare[@]}"); result="$work/compare/comparison.json"; kind=json ;;
    sweep) cmd=("${sweep[@]}"); result="$work/sweep.csv"; kind=csv ;;
  esac
  "$exe" "${cmd[@]}" >/dev/null 2>&1
  before=$(check $kind "$result")
  start=$(date +%s%N)
  "$exe" "${cmd[@]}" >/dev/null 2>&1
  full_ms=$(( ($(date +%s%N) - start) / 1000000 ))
  for k in 1 2 3 4 5 6 7 8; do
    "$exe" "${cmd[@]}" >/dev/null 2>&1 &
    pid=$!
    sleep "$(awk -v f="$full_ms" -v k=$k 'BEGIN { printf "%.3f", f * k / 8.0 / 1000 }')"
    kill -9 $pid 2>/dev/null || true
    wait $pid 2>/dev/null || true
    now=$(check $kind "$result") || { echo "$job: $result is partial after a kill at $k/8"; exit 1; }
    echo "$job killed at $k/8 of ${full_ms} ms: $result whole ($now; before $before)"
  done
done
echo "every interrupted write left a whole file"
