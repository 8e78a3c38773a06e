#!/usr/bin/env bash
# The man page help2man made at build time names every subcommand `springcheck --help` lists.
# Usage: man_page_test.sh SPRINGCHECK MAN_PAGE
set -euo pipefail
exe=$1 page=$2
grep -q '^\.SH NAME' "$page" || { echo "$page: no NAME section"; exit 1; }
subcommands=$("$exe" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && NF { print $1 }')
[ -n "$subcommands" ] || { echo "no subcommands in --help"; exit 1; }
for s in $subcommands; do
  grep -qxF "${s//-/\\-}" "$page" || { echo "$page lacks $s"; exit 1; }  # roff escapes -
done
echo "the man page names every subcommand: $(echo $subcommands)"
