#!/usr/bin/env bash
# Sweeps on a real scheduler. Installs Debian's Slurm and munge (if missing), starts a single-node
# cluster on this machine (controller and one node, localhost only, its own config, ports and
# state in a temporary folder), submits a small sweep with the documented job array
# (examples/slurm/submit.sh: one shard per task, then sweep-merge), waits, and checks the merged
# table equals a local run of the same sweep in every column but the timing ones. Needs root
# (the daemons); exits 77 (skipped) without it.
# Usage: slurm_test.sh SPRINGCHECK SOURCE_DIR
set -euo pipefail
exe=$(realpath "$1") src=$(realpath "$2")
spec=$src/tests/data/report_sweep.json shards=3
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: starting slurmctld, slurmd and munged needs root"
  exit 77
fi
"$src/scripts/install-packages.sh" slurm-wlm munge
tmp=$(mktemp -d)
fail() { echo "FAIL: $*"; for f in "$tmp"/out/slurm-*.log "$tmp"/log/*.log; do [ -f "$f" ] && { echo "== $f"; tail -20 "$f"; }; done; exit 1; }
stop_pid() { [ -s "$1" ] && kill "$(cat "$1")" 2>/dev/null || true; }
started_munge=
cleanup() {
  stop_pid "$tmp/run/slurmd.pid"
  stop_pid "$tmp/run/slurmctld.pid"
  [ -n "$started_munge" ] && stop_pid /run/munge/munged.pid
  sleep 1
  rm -rf "$tmp"
}
trap cleanup EXIT
start=$(date +%s)

# munge: Slurm's authentication. Use the machine's munged if one answers, else start one.
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  [ -s /etc/munge/munge.key ] || mungekey --create --keyfile=/etc/munge/munge.key
  chown munge:munge /etc/munge/munge.key && chmod 400 /etc/munge/munge.key
  mkdir -p /run/munge && chown munge:munge /run/munge
  runuser -u munge -- munged
  started_munge=1
  munge -n | unmunge >/dev/null || fail "munged does not answer"
fi

# The cluster: this host as controller and only node, on ports of its own.
host=$(hostname -s) cpus=$(nproc)
mkdir -p "$tmp"/{state,spool,run,log,out}
export SLURM_CONF=$tmp/slurm.conf
cat >"$SLURM_CONF" <<CONF
ClusterName=springcheck-test
SlurmctldHost=$host
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerParameters=kill_invalid_depend
ReturnToService=2
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
NodeName=$host CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -i
slurmd
for _ in $(seq 60); do
  [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
  sleep 1
done
[ "$(sinfo -h -o %T 2>/dev/null)" = idle ] || fail "the node never came up idle: $(sinfo 2>&1)"
echo "cluster up after $(($(date +%s) - start)) s"

# The documented job array, then the merge.
submitted=$(date +%s)
merge=$(SPRINGCHECK=$exe "$src/examples/slurm/submit.sh" "$spec" "$shards" "$tmp/out" --repeats 1)
for _ in $(seq 600); do
  [ -z "$(squeue -h 2>/dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue -h)" ] && echo "jobs done $(($(date +%s) - submitted)) s after submission" \
  || fail "jobs still queued after 600 s: $(squeue)"
[ -s "$tmp/out/all.csv" ] || fail "merge job $merge wrote no $tmp/out/all.csv"
for i in $(seq 0 $((shards - 1))); do
  [ -s "$tmp/out/part_$i.csv" ] || fail "task $i wrote no part_$i.csv"
done

# The same sweep here, and the two tables compared, timing columns aside (docs/timing.md).
"$exe" sweep "$spec" --out "$tmp/local.csv" --repeats 1 >/dev/null 2>&1 || fail "the local sweep failed"
python3 - "$tmp/out/all.csv" "$tmp/local.csv" <<'PY' || fail "the merged table differs from the local run"
import csv, sys
timing = {"wall_seconds", "wall_median_seconds", "realtime_factor", "repeats", "threads", "jobs",
          "load_average"}
merged, local = (list(csv.DictReader(open(p, newline=""))) for p in sys.argv[1:3])
assert merged and len(merged) == len(local), f"{len(merged)} merged rows, {len(local)} local"
assert list(merged[0]) == list(local[0]), "the columns differ"
for m, l in zip(merged, local):
    for column in m:
        if column not in timing and m[column] != l[column]:
            sys.exit(f"case {m['case_id']}: {column} is {m[column]} on Slurm, {l[column]} here")
print(f"{len(merged)} cases, {len(merged[0]) - len(timing)} columns: the Slurm table equals the local one")
PY
echo "slurm test took $(($(date +%s) - start)) s"
