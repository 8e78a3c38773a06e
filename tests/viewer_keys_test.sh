#!/usr/bin/env bash
# Presses every viewer key in a real window under Xvfb (xdotool, through the X server as a person
# would) and checks each does what docs/viewer.md says: the state line the viewer prints for the
# key, and the frame itself (screenshots with p): paused frames stay still, '.' moves the cloth,
# 'w' redraws it as springs and back, 'r' returns to t = 0, 't' shows the next scene.
# Usage: viewer_keys_test.sh SPRINGCHECK PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
B=$1 PY=$2 SRC=$3 OUT=$4
rm -rf "$OUT" && mkdir -p "$OUT"
cd "$SRC"
cat >"$OUT/drive.sh" <<DRIVE
#!/usr/bin/env bash
set -euo pipefail
"$B" view scenes/matched/cloth_hanging.json --screenshot-dir "$OUT" >"$OUT/log" 2>&1 &
viewer=\$!
# This viewer's own window (by its process: never another test's window on a shared display).
window=\$(xdotool search --sync --pid "\$viewer" --name "springcheck view" | head -1)
xdotool windowfocus --sync "\$window" 2>/dev/null || true
sleep 1
shots=0
press() {  # a key, then wait until the viewer has answered it
  local lines=\$(wc -l <"$OUT/log")
  xdotool key --window "\$window" "\$1"
  for _ in \$(seq 100); do [ "\$(wc -l <"$OUT/log")" -gt "\$lines" ] && return; sleep 0.05; done
  echo "no answer to key \$1"; exit 1
}
shot() { press p; shots=\$((shots + 1)); }
press space; shot; shot         # 1, 2: paused, twice
press period; shot              # 3: one step later
press w; shot                   # 4: springs
press w; shot                   # 5: shaded again
press r; shot                   # 6: back to t = 0
press d; press d; press s; press s; press i
press t; shot                   # 7: the next scene
# q closes the window on the key's press: the release xdotool sends next may find no window.
xdotool key --window "\$window" q 2>/dev/null || true
wait \$viewer
DRIVE
chmod +x "$OUT/drive.sh"
xvfb-run -a -s "-screen 0 1280x720x24" "$OUT/drive.sh"
cat "$OUT/log"
"$PY" - "$OUT" <<'PYEOF'
import re, sys
import matplotlib.image as mpimg
import numpy as np
out = sys.argv[1]
log = open(f"{out}/log").read()
def fail(message):
    sys.exit(f"FAIL: {message}")
def key_line(key, n=1):
    lines = [l for l in log.splitlines() if l.startswith(f"view: key {key}:")]
    if len(lines) < n:
        fail(f"no line for key {key} (#{n})")
    return lines[n - 1]
def time_of(line):
    return float(re.search(r"t ([0-9.]+) s", line).group(1))
def scene_of(line):
    return re.search(r"scene (\S+),", line).group(1)
shots = [mpimg.imread(f"{out}/springcheck-view-{n:03d}.png")[:, :, :3] for n in range(1, 8)]
h = shots[0].shape[0]
def view(img):  # the viewports: between the status band at the top and the key band at the bottom
    return img[int(0.1 * h):int(0.9 * h)]
def same(a, b):
    return np.abs(view(a) - view(b)).sum() == 0
if "paused" not in key_line("space"): fail("space did not pause")
if not same(shots[0], shots[1]): fail("a paused frame changed")
step = key_line("."); dt = float(re.search(r"dt ([0-9.e-]+) s", step).group(1))
if abs(time_of(step) - time_of(key_line("space")) - dt) > 1e-9: fail(". did not advance one step")
if same(shots[1], shots[2]): fail(". did not move the cloth")
if "springs" not in key_line("w", 1) or "shaded" not in key_line("w", 2): fail("w did not switch")
if same(shots[2], shots[3]): fail("w did not redraw the cloth as springs")
if not same(shots[2], shots[4]): fail("w twice did not give the same frame back")
if time_of(key_line("r")) != 0.0: fail("r did not return to t = 0")
if same(shots[4], shots[5]): fail("r did not change the frame")
if "wind on" not in key_line("d", 1) or "wind off" not in key_line("d", 2): fail("d did not toggle the wind")
if "swing on" not in key_line("s", 1) or "swing off" not in key_line("s", 2): fail("s did not toggle the swing")
before = re.search(r"mysim (\S+),", key_line("s", 2)).group(1)
after = re.search(r"mysim (\S+),", key_line("i")).group(1)
if before == after: fail("i did not change the integrator")
if scene_of(key_line("t")) == scene_of(key_line("i")): fail("t did not change the scene")
if same(shots[5], shots[6]): fail("t did not change the frame")
print("every key did what docs/viewer.md says")
PYEOF
