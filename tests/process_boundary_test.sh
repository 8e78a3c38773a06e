#!/usr/bin/env bash
# What an external engine starts ends with its run, and a signal to springcheck ends both:
#   process_boundary_test.sh SPRINGCHECK SCENE DATA_DIR
# For each way an engine can leave processes behind (tests/data/stray_engine.sh: a background
# child, a re-parented grandchild, a child in its own session, an engine past its time limit, an
# engine that joins springcheck's process group), springcheck exits 4 naming the engine, within
# a few seconds of the 2 s limit, and no process the engine started is alive, no scratch folder
# left. A parent that ignores SIGCHLD does not turn a failed engine into a success. SIGTERM and
# SIGINT during a run stop the engine and its child, remove the scratch, keep the previous
# results in --out and exit 128 + n.
set -u
exe=$1 scene=$2 data=$3
engines=$data/stray_engines.json
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export TMPDIR=$work/tmp STRAY_PIDS=$work/pids
mkdir -p "$TMPDIR"
fail() { echo "FAIL: $*"; cat "$work/log" 2>/dev/null; exit 1; }
alive() { [ -e "/proc/$1" ] && ! grep -q '^State:[[:space:]]*Z' "/proc/$1/status" 2>/dev/null; }
check_gone() {
  sleep 0.3
  [ -s "$STRAY_PIDS" ] || fail "$1: the engine recorded no pid"
  while read -r pid; do
    if alive "$pid"; then kill -9 "$pid"; fail "$1: process $pid left running"; fi
  done < "$STRAY_PIDS"
  [ -z "$(ls -A "$TMPDIR")" ] || fail "$1: scratch left in TMPDIR: $(ls "$TMPDIR")"
}

for mode in child-left grandchild-left setsid-left setsid-timeout joins-group; do
  : > "$STRAY_PIDS"
  start=$(date +%s)
  "$exe" run "$scene" --duration 0.2 --engine "$mode" --engines-file "$engines" \
    --out "$work/out_$mode" > "$work/log" 2>&1
  code=$?
  [ "$code" -eq 4 ] || fail "$mode: exit $code, expected 4"
  grep -q "engine '$mode'" "$work/log" || fail "$mode: the message does not name the engine"
  elapsed=$(( $(date +%s) - start ))
  [ "$elapsed" -le 8 ] || fail "$mode: took $elapsed s with a 2 s limit"
  check_gone "$mode"
  echo "ok: $mode (exit 4 in $elapsed s, nothing left)"
done

: > "$STRAY_PIDS"
( trap '' CHLD; exec "$exe" run "$scene" --duration 0.2 --engine exit-1 --engines-file "$engines" \
    --out "$work/out_sigchld" > "$work/log" 2>&1 )
code=$?
[ "$code" -eq 4 ] || fail "a parent ignoring SIGCHLD: exit $code, expected 4 (the engine exited 1)"
echo "ok: a parent that ignores SIGCHLD (exit 4)"

"$exe" run "$scene" --duration 0.2 --out "$work/kept" > "$work/log" 2>&1 || fail "the mysim run failed"
before=$(cd "$work/kept" && sha256sum * | sha256sum)
for signal in TERM INT; do
  : > "$STRAY_PIDS"
  # (set -m: a background job keeps SIGINT, which a non-interactive shell would otherwise ignore)
  set -m
  "$exe" run "$scene" --duration 0.2 --engine sleeper --engines-file "$engines" --out "$work/kept" \
    > "$work/log" 2>&1 &
  springcheck=$!
  set +m
  for _ in $(seq 100); do [ "$(wc -l < "$STRAY_PIDS")" -ge 2 ] && break; sleep 0.1; done
  [ "$(wc -l < "$STRAY_PIDS")" -ge 2 ] || fail "SIG$signal: the engine never started"
  kill -"$signal" "$springcheck"
  wait "$springcheck"
  code=$?
  expected=$([ "$signal" = TERM ] && echo 143 || echo 130)
  [ "$code" -eq "$expected" ] || fail "SIG$signal: exit $code, expected $expected"
  check_gone "SIG$signal"
  after=$(cd "$work/kept" && sha256sum * | sha256sum)
  [ "$before" = "$after" ] || fail "SIG$signal: the previous results in --out changed"
  echo "ok: SIG$signal (exit $code, engine and child stopped, scratch removed, results kept)"
done
