#!/usr/bin/env bash
# Every command lists the same engines: the registry's, a user's engines file included.
#   `springcheck list` prints them; `compare` and `suite` run them all by default (each run,
#   refused or failed engine is in comparison.json); every command that takes engines names the
#   built-in ones in its help.
# Usage: engines_listed_test.sh SPRINGCHECK PYTHON SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 python=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work/scenes"
engines_file="$src/examples/external/engines.json"
cp "$src/scenes/seed/pendulum.json" "$work/scenes/"

listed=$("$exe" list "$work/scenes" --engines-file "$engines_file" |
         sed -n '/^Engines:/,/^Scenes/p' | sed -n 's/^  \([^ []*\).*/\1/p' | sort | tr '\n' ' ')
echo "list: $listed"
[[ "$listed" == *pysim* && "$listed" == *bullet-implicit* ]] || { echo "list misses engines"; exit 1; }

ran() {  # engine names in a comparison.json: runs, refusals and failures
  "$python" -c 'import json, sys
c = json.load(open(sys.argv[1]))
names = [e["engine"] for e in c["engines"]] + [r["engine"] for r in c["refused"] + c["failed"]]
print(" ".join(sorted(names)) + " ")' "$1"
}
"$exe" compare "$work/scenes/pendulum.json" --engines-file "$engines_file" --out "$work/compare" >/dev/null
"$exe" suite "$work/scenes" --engines-file "$engines_file" --out "$work/suite" >/dev/null
for table in "$work/compare/comparison.json" "$work/suite/pendulum/comparison.json"; do
  got=$(ran "$table")
  echo "$table: $got"
  [ "$got" == "$listed" ] || { echo "engines differ from list: $got vs $listed"; exit 1; }
done

builtin=$("$exe" list "$work/scenes" | sed -n '/^Engines:/,/^Scenes/p' | sed -n 's/^  \([^ []*\).*/\1/p')
for command in run compare suite gate sweep stability recommend list view; do
  help=$("$exe" "$command" --help 2>&1 || true)
  [[ "$help" == *"requires"* || "$help" == *"A subcommand"* ]] && continue  # view without a viewer
  for engine in $builtin; do
    [[ "$help" == *"$engine"* ]] || { echo "springcheck $command --help does not list $engine"; exit 1; }
  done
done
echo "every command lists the same engines"
