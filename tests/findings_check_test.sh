#!/usr/bin/env bash
# scripts/check-findings.py holds a quoted number to its table: it passes a number the table
# rounds to, and refuses one the table contradicts, a check whose number the text does not quote,
# and a check of a row the table does not have.
# Usage: findings_check_test.sh PYTHON SOURCE_DIR WORK_DIR
set -uo pipefail
py=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work/out/stability"
fail() { echo "FAIL: $*"; exit 1; }
cat > "$work/out/stability/map.csv" <<'CSV'
engine,mass_ratio,ratio
mysim:rk4,1,1.0002
mysim:rk4,10000,0.8965
mysim:verlet,1,0.957
CSV
claim() {  # claim TEXT: a findings file of one paragraph
  printf '# Findings\n\n%s\n' "$1" > "$work/findings.md"
  "$py" "$src/scripts/check-findings.py" "$work/findings.md" "$work/out"
}
claim 'RK4 reaches x0.90 <!-- check stability/map.csv | ratio | engine=mysim:rk4; mass_ratio=10000 | one | 0.90 --> of theory, at best x1.000 <!-- check stability/map.csv | ratio | engine=mysim:rk4 | max | 1.000 -->.' \
  || fail "a number its table rounds to was refused"
claim 'RK4 reaches x0.96 <!-- check stability/map.csv | ratio | engine=mysim:rk4; mass_ratio=10000 | one | 0.96 -->.' \
  && fail "a number its table contradicts (0.8965 quoted as 0.96) passed"
claim 'RK4 reaches x0.96 of theory <!-- check stability/map.csv | ratio | engine=mysim:rk4; mass_ratio=10000 | one | 0.90 -->.' \
  && fail "a check of a number the text does not quote passed"
claim 'VBD reaches x0.5 <!-- check stability/map.csv | ratio | engine=mysim:vbd | one | 0.5 -->.' \
  && fail "a check of a row the table does not have passed"
claim 'Forty per cent: 40 % <!-- check stability/map.csv | ratio | engine=mysim:verlet | one | 40 x100 -->.' \
  && fail "0.957 quoted as 40 % passed"
claim 'Nothing checked here: 0.5.' && fail "a findings file with no checks passed"
echo "check-findings: passes what the table holds, refuses what it contradicts"
