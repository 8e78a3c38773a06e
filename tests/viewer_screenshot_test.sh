#!/usr/bin/env bash
# Opens the viewer on the cloth under Xvfb (Mesa's software OpenGL), saves a screenshot and
# checks that both viewports show the cloth: enough cloth-coloured pixels in the middle of each
# half, where the hanging cloth is drawn; and that the (compressed) PNG stays under 300 KiB.
# Usage: viewer_screenshot_test.sh SPRINGCHECK PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
B=$1 PY=$2 SRC=$3 OUT=$4
mkdir -p "$OUT"
rm -f "$OUT/view.png"
cd "$SRC"
xvfb-run -a -s "-screen 0 1280x720x24" "$B" view scenes/matched/cloth_hanging.json \
  --engines mysim,bullet-deformable --frames 30 --screenshot "$OUT/view.png"
size=$(stat -c %s "$OUT/view.png")
echo "screenshot: $size bytes"
[ "$size" -lt $((300 * 1024)) ] || { echo "FAIL: the screenshot is $size bytes, over 300 KiB"; exit 1; }
"$PY" - "$OUT/view.png" <<'PYEOF'
import sys
import matplotlib.image as mpimg
img = mpimg.imread(sys.argv[1])[:, :, :3]
h, w, _ = img.shape
assert (w, h) == (1280, 640), f"unexpected size {w}x{h}"
background = img[h - 60, w // 4]  # below the cloth, above the key line
for half, name in ((0, "mysim"), (1, "bullet-deformable")):
    region = img[int(0.2 * h):int(0.85 * h), half * w // 2 + int(0.1 * w / 2):(half + 1) * w // 2 - int(0.1 * w / 2)]
    red = region[:, :, 0]
    cloth = ((red > region[:, :, 1] + 0.08) & (red > region[:, :, 2] + 0.08)).sum()
    differs = (abs(region - background).sum(axis=2) > 0.1).sum()
    print(f"{name}: {cloth} cloth-coloured pixels, {differs} differ from the background")
    assert cloth > 5000, f"{name} viewport shows no cloth"
PYEOF
