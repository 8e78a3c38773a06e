#!/usr/bin/env python3
"""The main job's budget, held by counts: each stage's work (runs and steps, from
out/timings.json) against its record (scripts/main-job-work.json). Fails when a stage does more
than 20 % more work than its record, runs a stage the record does not list or skips one it does;
and when a stage's work fell more than 20 % below its record (lower the record, so the next
growth is measured from there). Counts, not seconds: the same on any machine and at any load.

Usage: check-main-job-work.py TIMINGS_JSON RECORD_JSON
"""
import json
import sys

# 20 %: the bound. A stage's counts are exact (the same input gives the same runs and
# steps), so any change is a change of the work itself; 20 % lets small additions through and
# stops a stage from quietly doubling.
GROWTH = 0.20


def load(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"error: {path}: cannot read {what}: {e}")


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__.strip().splitlines()[-1])
    timings, record = load(argv[1], "the main job's timings"), load(argv[2], "the work record")
    measured = {s["name"]: s for s in timings.get("stages", [])}
    recorded = record.get("stages", {})
    problems = []
    for name, rec in recorded.items():
        got = measured.get(name)
        if got is None or "runs" not in got:
            problems.append(f"{name}: recorded but not run (or run without work counts)")
            continue
        for unit in ("runs", "steps"):
            was, now = rec[unit], got[unit]
            line = f"{name}: {now} {unit}, recorded {was}"
            if now > was * (1 + GROWTH):
                problems.append(f"{line} (+{100 * (now / max(was, 1) - 1):.0f} %, more than "
                                f"{100 * GROWTH:.0f} %): cut the stage's work, or move it behind the heavier command")
            elif now < was * (1 - GROWTH):
                problems.append(f"{line} ({100 * (now / max(was, 1) - 1):.0f} %): lower the record in {argv[2]}")
            else:
                print(f"ok: {line}")
    for name in measured:
        if name not in recorded:
            problems.append(f"{name}: run but not recorded in {argv[2]}")
    for p in problems:
        print(f"FAIL: {p}")
    print(f"main job work: {len(recorded) - sum(1 for p in problems if ': recorded' in p)} stages checked, "
          f"{len(problems)} over or under their record")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
