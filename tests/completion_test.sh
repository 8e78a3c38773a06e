#!/usr/bin/env bash
# The bash completion springcheck prints completes its subcommands and each one's options, and
# every subcommand of `springcheck --help` is in it.
# Usage: completion_test.sh SPRINGCHECK
set -euo pipefail
exe=$1
eval "$("$exe" completion bash)"
complete_words() {  # the words of a command line being completed (the last may be partial)
  COMP_WORDS=("$@")
  COMP_CWORD=$(( $# - 1 ))
  COMPREPLY=()
  _springcheck
  echo "${COMPREPLY[*]}"
}
expect() {  # got wanted...
  local got=$1; shift
  for w in "$@"; do
    [[ " $got " == *" $w "* ]] || { echo "completion lacks '$w' (got: $got)"; exit 1; }
  done
}
expect "$(complete_words springcheck sw)" sweep sweep-merge
expect "$(complete_words springcheck gate --ju)" --junit
expect "$(complete_words springcheck recommend --max)" --max-error
expect "$(complete_words springcheck sweep spec.json --rep)" --repeats
[ "$(complete_words springcheck gate --max)" == "" ] || { echo "gate has no --max-error"; exit 1; }
# Every subcommand the help lists.
subcommands=$("$exe" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && NF { print $1 }')
[ -n "$subcommands" ] || { echo "no subcommands in --help"; exit 1; }
expect "$(complete_words springcheck '')" $subcommands
echo "completion offers every subcommand and their options"
