#!/usr/bin/env bash
# The Debian package, as a user gets it: built with CPack from this build, its file list and
# declared dependencies checked (dpkg-deb -c, -f), unpacked into a temporary root (dpkg -x) and
# used from an unrelated folder with no source or build tree behind it: engine init, run, gate
# (JUnit) and report. Also: the report's interpreter is found at run time, and one without
# matplotlib is named in a clear error.
#   package_test.sh BUILD_DIR
set -u
build=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

(cd "$build" && cpack -G DEB -B "$work/pkg" > "$work/cpack.log" 2>&1) || fail "cpack: $(tail -5 "$work/cpack.log")"
deb=$(ls "$work"/pkg/springcheck_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || fail "no springcheck_*.deb in $work/pkg"
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"

dpkg-deb -c "$deb" | awk '{print $6}' > "$work/files"
for f in ./usr/bin/springcheck ./usr/share/springcheck/reports/make_report.py \
         ./usr/share/springcheck/scenes/matched/cloth_hanging.json \
         ./usr/share/springcheck/compare/tolerances.json \
         ./usr/share/springcheck/examples/external/pysim.py \
         ./usr/share/man/man1/springcheck.1.gz ./usr/share/bash-completion/completions/springcheck \
         ./usr/lib/libspringcheck_mysim.a ./usr/include/mysim/model.h \
         ./usr/lib/cmake/springcheck/springcheckConfig.cmake; do
  grep -qx "$f" "$work/files" || fail "the package lacks $f"
done
outside=$(grep -v '^\./usr/' "$work/files" | grep -vx '\./' | grep -vx '\./usr/')
[ -z "$outside" ] || fail "files outside /usr: $outside"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for d in libbullet3.24 libglfw3 libpng16-16 libgomp1 libstdc++6 python3-numpy python3-matplotlib; do
  echo "$depends" | grep -q "\b$d\b" || fail "Depends lacks $d"
done
version=$(dpkg-deb -f "$deb" Version)
built=$("$build/cli/springcheck" --version | cut -d' ' -f2)
[ "$version" = "$built" ] || fail "package version $version, springcheck --version says $built"

dpkg -x "$deb" "$work/root"
exe=$work/root/usr/bin/springcheck
mkdir -p "$work/elsewhere" && cd "$work/elsewhere" || fail "cd"
unset SPRINGCHECK_DATA_DIR
"$exe" --version | grep -q "^springcheck $version (commit " || fail "--version: $("$exe" --version)"
"$exe" gate --help | grep -q "$work/root/usr/share/springcheck/compare/tolerances.json" \
  || fail "the unpacked binary's data folder is not its own: $("$exe" gate --help | grep tolerances)"

"$exe" engine init mine --name mine > "$work/init.log" 2>&1 || fail "engine init: $(cat "$work/init.log")"
"$exe" run "$work/root/usr/share/springcheck/scenes/matched/chain_hanging.json" --duration 2 \
  --out out/chain_hanging/mysim > "$work/run.log" 2>&1 || fail "run: $(tail -3 "$work/run.log")"
[ -s out/chain_hanging/mysim/summary.json ] || fail "run wrote no summary.json"
"$exe" gate --tolerances mine/tolerances.json --junit gate.xml > "$work/gate.log" 2>&1 \
  || fail "the skeleton's gate: $(tail -5 "$work/gate.log")"
grep -q '<testsuite[^>]*failures="0"' gate.xml || fail "gate.xml: $(head -3 gate.xml)"
[ "$(grep -c '<testcase' gate.xml)" -ge 4 ] || fail "gate.xml holds fewer than 4 checks"
"$exe" report --results out --out report > "$work/report.log" 2>&1 \
  || fail "report: $(tail -5 "$work/report.log")"
[ -s report/report.pdf ] || fail "no report.pdf"

# The interpreter is chosen at run time: SPRINGCHECK_PYTHON without matplotlib is refused by name.
printf '#!/bin/sh\necho "ModuleNotFoundError: No module named '"'"'matplotlib'"'"'" >&2\nexit 1\n' > "$work/python3"
chmod +x "$work/python3"
if SPRINGCHECK_PYTHON=$work/python3 "$exe" report --results out --out report2 > "$work/nopy.log" 2>&1; then
  fail "report ran with an interpreter that has no matplotlib"
fi
grep -q "SPRINGCHECK_PYTHON=$work/python3 is not a python3 with numpy and matplotlib" "$work/nopy.log" \
  || fail "the error does not name the interpreter: $(cat "$work/nopy.log")"
grep -q "No module named 'matplotlib'" "$work/nopy.log" || fail "the error does not say what is missing"
echo "ok: built, listed, unpacked, and engine init, run, gate and report work from the unpacked root"
