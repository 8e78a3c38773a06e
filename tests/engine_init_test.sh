#!/usr/bin/env bash
# springcheck engine init: the skeleton runs and passes its own gate as written, through the
# suite of matched scenes, from a folder unrelated to springcheck's; a non-empty folder and a
# built-in engine's name are refused, changing nothing.
#   engine_init_test.sh SPRINGCHECK
set -u
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$work/unrelated" && cd "$work/unrelated" || fail "cd"

"$exe" engine init "$work/x" --name first > log 2>&1 || fail "engine init: $(cat log)"
for f in first.py engines.json tolerances.json README.md; do
  [ -s "$work/x/$f" ] || fail "engine init wrote no $f"
done
# The README's own suite command, as written (it names the matched scenes' folder), must pass:
# exit 0, not 3 (run on every shipped scene, the explicit skeleton blows up on the material
# scenes' 2 ms step).
suggested=$(grep -m1 '^springcheck suite ' "$work/x/README.md" | sed 's/ *#.*//')
[ -n "$suggested" ] || fail "the README suggests no suite command"
eval "\"\$exe\" ${suggested#springcheck } --out \"\$work/suite\"" > suite.log 2>&1 \
  || fail "the README's suite command exits $?: $(tail -8 suite.log)"
grep -q "gate: [0-9]* passed, 0 failed" suite.log || fail "no passing gate line: $(tail -3 suite.log)"
[ -d "$work/suite/cloth_hanging/first" ] || fail "the suite did not run the engine on cloth_hanging"
# Only the engines its checks name (the README's --engines): no Bullet engine the checks leave out.
[ ! -e "$work/suite/cloth_hanging/bullet-classic" ] || fail "the suite ran bullet-classic, which no check names"
[ -d "$work/suite/cloth_hanging/bullet-deformable" ] || fail "the suite did not run bullet-deformable, which a check names"
echo "ok: the skeleton passes its suite and gate from an unrelated folder"

before=$(ls -l "$work/x")
if "$exe" engine init "$work/x" --name second > log 2>&1; then fail "a non-empty folder was written into"; fi
grep -q "not an empty folder" log || fail "the refusal does not say why: $(cat log)"
[ "$(ls -l "$work/x")" = "$before" ] || fail "the refused init changed the folder"
if "$exe" engine init "$work/y" --name mysim > log 2>&1; then fail "a built-in name was taken"; fi
grep -q "built-in engine" log || fail "the refusal does not say why: $(cat log)"
[ ! -e "$work/y" ] || fail "a refused init created its folder"
echo "ok: a non-empty folder and a built-in name are refused, nothing written"
