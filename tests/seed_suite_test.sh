#!/usr/bin/env bash
# `springcheck suite` runs every seed scene in mysim, bullet-deformable and bullet-implicit: none
# of the three refuses one, none blows up (exit 0), and each writes its run.
# Usage: seed_suite_test.sh SPRINGCHECK PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
rm -rf "$work"
"$exe" suite "$src/scenes/seed" --out "$work" >/dev/null
"$python" - "$work" "$src/scenes/seed" <<'PY'
import json, os, sys
work, seeds = sys.argv[1], sys.argv[2]
scenes = sorted(f[:-5] for f in os.listdir(seeds) if f.endswith(".json"))
assert len(scenes) >= 7, scenes
for scene in scenes:
    c = json.load(open(os.path.join(work, scene, "comparison.json")))
    ran = {e["engine"]: e for e in c["engines"]}
    for engine in ("mysim", "bullet-deformable", "bullet-implicit"):
        assert engine in ran, f"{scene}: {engine} did not run: {c['refused'] + c['failed']}"
        assert not ran[engine]["blowup"], f"{scene}: {engine} blew up"
    print(f"{scene}: " + ", ".join(sorted(ran)))
PY
