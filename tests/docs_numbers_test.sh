#!/usr/bin/env bash
# The docs cite no report page by number (pages move as results come and go: findings once cited
# page 7 for what was page 25) and give no fixed page count: a page is named by its title.
#   docs_numbers_test.sh SOURCE_DIR
set -u
src=$1
found=$(grep -nE '\b[Rr]eport page [0-9]+|\([Pp]age [0-9]+\)|\bp\. ?[0-9]+\b|\b[0-9]+ pages\b' \
  "$src"/README.md "$src"/docs/*.md)
if [ -n "$found" ]; then
  echo "FAIL: page numbers in the docs:"
  echo "$found"
  exit 1
fi
echo "ok: no page numbers or page counts in README.md and docs/"
