#!/usr/bin/env bash
# run --obj-frames: one OBJ per sampled frame, numbered from 0, with obj/times.csv; a cloth as its
# mesh with one normal per vertex, a chain as its springs drawn as lines; the last frame's
# vertices are final_state.csv's positions; a run without the flag leaves no obj/ behind.
#   obj_frames_test.sh SPRINGCHECK SOURCE_DIR
set -u
exe=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$exe" run "$src/scenes/matched/cloth_hanging.json" --duration 0.4 --obj-frames --out "$work/cloth" \
  >/dev/null || fail "run --obj-frames"
frames=$(($(wc -l < "$work/cloth/obj/times.csv") - 1))
[ "$frames" -gt 10 ] || fail "only $frames frames in obj/times.csv"
[ "$(ls "$work/cloth/obj" | grep -c '^frame_[0-9]\{5\}\.obj$')" -eq "$frames" ] \
  || fail "$(ls "$work/cloth/obj" | grep -c obj) OBJ files for $frames frames"
last=$(printf '%s/cloth/obj/frame_%05d.obj' "$work" $((frames - 1)))
for kind in v vn; do
  [ "$(grep -c "^$kind " "$last")" -eq 144 ] || fail "$kind lines: $(grep -c "^$kind " "$last"), expected 144 (12 x 12)"
done
[ "$(grep -c '^f ' "$last")" -eq 242 ] || fail "f lines: $(grep -c '^f ' "$last"), expected 2 x 11 x 11"
# The last frame's first vertex is final_state.csv's particle 0, to the OBJ's 9 digits.
awk -F, 'NR == 2 {printf "%.6f %.6f %.6f\n", $2, $3, $4}' "$work/cloth/final_state.csv" > "$work/a"
awk '/^v / {printf "%.6f %.6f %.6f\n", $2, $3, $4; exit}' "$last" > "$work/b"
cmp -s "$work/a" "$work/b" || fail "last frame vertex 0 $(cat "$work/b"), final state $(cat "$work/a")"

"$exe" run "$src/scenes/matched/chain_hanging.json" --duration 0.2 --obj-frames --out "$work/chain" \
  >/dev/null || fail "chain run --obj-frames"
[ "$(grep -c '^l ' "$work/chain/obj/frame_00000.obj")" -eq 8 ] || fail "chain: not 8 springs as lines"
"$exe" run "$src/scenes/matched/cloth_hanging.json" --duration 0.2 --out "$work/cloth" >/dev/null \
  || fail "run without the flag"
[ ! -e "$work/cloth/obj" ] || fail "obj/ of the previous run left beside a run without it"
echo "ok: $frames numbered OBJ frames with normals, a chain as lines, none left by a later run"
