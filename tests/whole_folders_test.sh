#!/usr/bin/env bash
# A result folder holds one whole run or the previous one, never a mix:
#   whole_folders_test.sh SPRINGCHECK SCENE
# Two runs of different integrators into the same --out at the same moment, ten times: the folder
# always holds one of them whole (every file equal to that integrator's own run). A folder that
# holds a file springcheck does not write is refused, naming it, and left as it was.
set -u
exe=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
for integrator in verlet symplectic-euler; do
  "$exe" run "$scene" --integrator "$integrator" --duration 1 --out "$work/ref_$integrator" >/dev/null \
    || fail "reference run $integrator"
done
for round in $(seq 10); do
  "$exe" run "$scene" --integrator verlet --duration 1 --out "$work/both" >/dev/null 2>&1 &
  a=$!
  "$exe" run "$scene" --integrator symplectic-euler --duration 1 --out "$work/both" >/dev/null 2>&1 &
  b=$!
  wait $a; wait $b
  winner=$(grep -o '"integrator": "[a-z-]*"' "$work/both/summary.json" | cut -d'"' -f4)
  [ -n "$winner" ] || fail "round $round: no summary.json"
  for f in final_state.csv trajectory.npy times.npy energy.csv; do
    cmp -s "$work/both/$f" "$work/ref_$winner/$f" || fail "round $round: $f is not $winner's"
  done
  [ -z "$(ls -A "$work" | grep staging)" ] || fail "round $round: a staging folder left"
done
echo "ok: 10 rounds of two runs at once, each folder one whole run"

mkdir -p "$work/mine" && echo "my notes" > "$work/mine/notes.txt"
if "$exe" run "$scene" --duration 0.2 --out "$work/mine" > "$work/log" 2>&1; then
  fail "a folder with notes.txt was replaced"
fi
grep -q "notes.txt" "$work/log" || fail "the refusal does not name notes.txt: $(cat "$work/log")"
[ "$(ls "$work/mine")" = "notes.txt" ] || fail "the user's folder changed"
echo "ok: a folder of the user's is refused and left as it was"

# A write that fails for want of space (a file-size limit stands in for a full disk: the write
# fails with EFBIG as it would with ENOSPC): the run fails naming the file, the folder keeps the
# previous run whole, and no staging folder is left.
"$exe" run "$scene" --duration 1 --out "$work/full" >/dev/null || fail "first run into full"
cp -r "$work/full" "$work/full_before"
if (trap '' XFSZ; ulimit -f 40; "$exe" run "$scene" --integrator verlet --duration 1 \
      --out "$work/full") > "$work/full_log" 2>&1; then
  fail "a run whose write failed exited 0"
fi
grep -q "cannot write $work/full/trajectory.npy" "$work/full_log" \
  || fail "the failed write is not named: $(cat "$work/full_log")"
grep -q "keeps its previous results" "$work/full_log" || fail "no word on the folder: $(cat "$work/full_log")"
diff -r "$work/full" "$work/full_before" >/dev/null || fail "the previous results changed"
[ -z "$(ls -A "$work" | grep staging)" ] || fail "a staging folder left after the failed write"
echo "ok: a write that fails mid-run leaves the previous results whole and says so"

# A staging folder left by a springcheck that died mid-write (its pid gone) is removed by the
# next write beside it; one of a live process is left alone.
sleep 0 & dead=$!; wait "$dead"  # reaped: no process has this pid now
mkdir -p "$work/.full.staging.$dead.1" "$work/.full.staging.$$.1"
echo half > "$work/.full.staging.$dead.1/trajectory.npy"
"$exe" run "$scene" --duration 0.2 --out "$work/full" >/dev/null || fail "run beside a dead staging folder"
[ ! -e "$work/.full.staging.$dead.1" ] || fail "a dead run's staging folder was left"
[ -d "$work/.full.staging.$$.1" ] || fail "a live process's staging folder was removed"
echo "ok: a dead run's staging folder is cleared by the next write"

# --out given as a link to a folder: followed (the results land in the folder it names, the link
# stays a link); a link to nothing is refused with a message, nothing written.
mkdir -p "$work/real_results" && ln -s "$work/real_results" "$work/linked"
"$exe" run "$scene" --duration 0.2 --out "$work/linked" > "$work/link_log" 2>&1 \
  || fail "--out as a link to a folder: $(cat "$work/link_log")"
[ -L "$work/linked" ] || fail "the link was replaced"
[ -s "$work/real_results/summary.json" ] || fail "the results are not in the linked folder"
"$exe" run "$scene" --duration 0.2 --out "$work/linked" > "$work/link_log" 2>&1 \
  || fail "a second run through the link: $(cat "$work/link_log")"
ln -s "$work/nowhere" "$work/dangling"
if "$exe" run "$scene" --duration 0.2 --out "$work/dangling" > "$work/link_log" 2>&1; then
  fail "a link to nothing was written through"
fi
grep -q "a symbolic link to" "$work/link_log" || fail "no word on the link: $(cat "$work/link_log")"
[ ! -e "$work/nowhere" ] || fail "the dangling link's target was created"
echo "ok: --out as a link to a folder is followed; a link to nothing is refused"
