#!/bin/sh
# springcheck refine on the cantilever strip: the tip drop converges at second order to within
# 0.5 % of the heavy elastica at 16 cells (measured: order 2.10, -0.075 %), the flex-spring strip
# converges at no better than first order (measured 0.88) to a strip with no bending stiffness
# (chord near 90 degrees), and a scene without a material is refused naming system.material.
# ctest-label: cli physics
set -eu
exe=$1
root=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$exe" refine "$root/scenes/material/cantilever_strip.json" \
  "$root/scenes/material/cantilever_strip_flex.json" --resolutions 3,6,12 --out "$out/r" >/dev/null
est="$out/r/refine_estimates.csv"
# columns: scene,bending,engine,quantity,unit,finest_resolution,finest,observed_order,
#          extrapolated_limit,finest_vs_limit_rel,reference,finest_vs_reference_rel,note
awk -F, '$1 == "cantilever_strip" && $4 == "tip_drop" {
  found = 1
  if ($8 < 1.8 || $8 > 2.4) { print "tip drop order " $8 ", expected about 2"; exit 1 }
  rel = $12 < 0 ? -$12 : $12
  if (rel > 0.005) { print "tip drop " $12 " from the elastica, expected within 0.5 %"; exit 1 }
}
$1 == "cantilever_strip_flex" && $4 == "tip_drop" {
  flex = 1
  if ($8 != "" && $8 > 1.5) { print "flex strip order " $8 ", expected at most first order"; exit 1 }
}
$1 == "cantilever_strip_flex" && $4 == "chord_angle" && $7 < 80 {
  print "flex strip chord " $7 " deg: expected it near vertical"; exit 1
}
END { if (!found || !flex) { print "missing rows in " FILENAME; exit 1 } }' "$est"
if "$exe" refine "$root/scenes/matched/chain_hanging.json" --out "$out/bad" 2>"$out/err"; then
  echo "refine accepted a scene without a material"; exit 1
fi
grep -q "system.material" "$out/err" || { cat "$out/err"; exit 1; }
echo "refine: order and elastica within bounds"
