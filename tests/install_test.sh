#!/usr/bin/env bash
# springcheck as another project sees it: install the build into a temporary prefix and, from an
# unrelated folder with only the installed tree, run a scene, draw the report, find every default
# path inside the prefix, and build and run the consumer project (examples/consumer: a custom
# integrator through the public API) against the installed package.
# Usage: install_test.sh BUILD_DIR [EXTRA_CXX_FLAGS]
set -euo pipefail
build=$1 cxx_flags=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
exe=$prefix/bin/springcheck
data=$prefix/share/springcheck
mkdir "$tmp/work" && cd "$tmp/work"
fail() { echo "FAIL: $*"; exit 1; }

# Every default path lies inside the prefix, not in the source or build tree.
"$exe" gate --help | grep -qF "$data/compare/tolerances.json" || fail "gate's default tolerances are not $data/compare/tolerances.json"
"$exe" suite --help | grep -qF "$data/scenes" || fail "suite's default scene folder is not $data/scenes"
[ -s "$prefix/share/man/man1/springcheck.1.gz" ] || fail "no installed man page"
bash -c "source '$prefix/share/bash-completion/completions/springcheck' && complete -p springcheck" >/dev/null \
  || fail "the installed completion does not register springcheck"

# A run and its report, from here.
"$exe" run "$data/scenes/matched/chain_hanging.json" --duration 2 >/dev/null
[ -s out/chain_hanging/mysim/summary.json ] || fail "springcheck run wrote no out/chain_hanging/mysim/summary.json"
"$exe" report >report.log 2>&1 || { cat report.log; fail "springcheck report failed"; }
[ -s out/report/report.pdf ] || fail "springcheck report wrote no out/report/report.pdf"

# Without its data the binary says where it looked, and fails.
if SPRINGCHECK_DATA_DIR=$tmp/nowhere "$exe" report >missing.log 2>&1; then fail "report ran without its script"; fi
grep -qF "$tmp/nowhere/reports/make_report.py" missing.log || { cat missing.log; fail "the error does not name the missing script"; }

# The consumer project, built against the install only.
cmake -S "$data/examples/consumer" -B consumer -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS=$cxx_flags" >consumer.log 2>&1 \
  || { cat consumer.log; fail "the consumer project does not configure against the install"; }
cmake --build consumer >>consumer.log 2>&1 || { cat consumer.log; fail "the consumer project does not build"; }
consumer/midpoint_check | tee midpoint.log || fail "the consumer's midpoint integrator missed the chain's closed form"
grep -q "^midpoint .*status ok" midpoint.log || fail "the consumer did not run its own integrator"
echo "installed springcheck runs, reports and builds a consumer from $tmp"
