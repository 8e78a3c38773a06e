#!/usr/bin/env bash
# A sweep on a Slurm cluster: a job array of SHARDS tasks (sweep_shard.sbatch, one shard each),
# then a job that merges the shards into OUT/all.csv once every task has succeeded. Prints the
# merge job's id (wait for it with `squeue -j ID`, or submit more work with
# --dependency=afterok:ID). Logs go to OUT/slurm-*.log.
# Usage: submit.sh SWEEP.json SHARDS OUT [more sweep options, e.g. --repeats 1]
# The springcheck to run: $SPRINGCHECK, else the one on PATH.
set -euo pipefail
if (($# < 3)); then
  echo "usage: $0 SWEEP.json SHARDS OUT [sweep options...]" >&2
  exit 2
fi
spec=$(realpath "$1") shards=$2 out=$(realpath -m "$3")
shift 3
springcheck=$(command -v "${SPRINGCHECK:-springcheck}") || {
  echo "submit.sh: no springcheck on PATH (set SPRINGCHECK)" >&2
  exit 2
}
mkdir -p "$out"
array=$(sbatch --parsable --array="0-$((shards - 1))" --output="$out/slurm-%A_%a.log" \
  "$(dirname "$0")/sweep_shard.sbatch" "$springcheck" "$spec" "$shards" "$out" "$@")
sbatch --parsable --dependency="afterok:${array%%;*}" --job-name=springcheck-merge \
  --output="$out/slurm-merge-%j.log" \
  --wrap "'$springcheck' sweep-merge '$out/all.csv' '$out'/part_*.csv"
