#!/usr/bin/env python3
"""bench/scale_study.py on tiny cloths: a row per engine and size, each run a process of its own.

Usage: scale_study_test.py SPRINGCHECK SOURCE_DIR WORK_DIR SPEC. Runs the study of SPEC
(bench/scale_study.json, bench/equal_error_study.json) at 6 and 10 cells a side (milliseconds
each) and checks what its table must say whatever the machine: every engine at every size, every
run whole ("ok"), the fixed-count forms at exactly their 10 passes a step (the two runs'
difference, so a broken difference shows), and memory figures that are numbers. Exit 1 naming
the first row that fails.
"""
import csv
import json
import math
import pathlib
import shutil
import subprocess
import sys


def main(springcheck, source, work, spec):
    source, work = pathlib.Path(source), pathlib.Path(work)
    shutil.rmtree(work, ignore_errors=True)
    spec = source / spec
    done = subprocess.run([sys.executable, str(source / "bench/scale_study.py"), springcheck,
                           str(spec), str(work), "--resolutions", "6,10", "--steps", "2"],
                          capture_output=True, text=True)
    if done.returncode != 0:
        print(f"scale_study.py exited {done.returncode}: {done.stderr}")
        return 1
    rows = list(csv.DictReader(open(work / "scale.csv")))
    engines = json.loads(spec.read_text())["engines"]
    expected = {(e, n) for e in engines for n in ("6", "10")}
    got = {(r["engine"], r["cells"]) for r in rows}
    if got != expected:
        print(f"rows for {sorted(got)}, expected {sorted(expected)}")
        return 1
    for r in rows:
        where = f"{r['engine']} at {r['cells']} cells"
        if r["status"] != "ok":
            print(f"{where}: status {r['status']}")
            return 1
        if "tolerance=0" in r["engine"] and float(r["passes_per_step"]) != 10:
            print(f"{where}: {r['passes_per_step']} passes a step, its fixed count is 10")
            return 1
        figures = ("peak_mib", "bytes_per_node", "ms_per_step")
        if not all(math.isfinite(float(r[k])) for k in figures):
            print(f"{where}: a figure is not a number: {r}")
            return 1
    print(f"{len(rows)} rows: every engine of {spec.name} at 6 and 10 cells, "
          "any fixed count at its 10 passes")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
