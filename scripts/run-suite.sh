#!/usr/bin/env bash
# The main job: set up (install what is missing), build, run the default comparison suite and
# write the report (the stages: scripts/main-job.sh; what each writes is listed there).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh default springcheck springcheck_bench
exec scripts/main-job.sh
