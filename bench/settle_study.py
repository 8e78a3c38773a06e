#!/usr/bin/env python3
"""Where each solver family settles the check cloth, against backward Euler (issue 36).

Usage: settle_study.py SPRINGCHECK OUT_DIR [--cells 128] [--duration 24] [--threads 1]
                       [--engines mysim:backward-euler,mysim:xpbd,...] [--compare-only]

The check cloth (bench/scale_study.json's base: 1 m, 0.5 kg, structural and shear 100 N/m, flex
10 N/m, drag 2/s, top corners pinned, dropped from horizontal) at CELLS x CELLS nodes, run for
DURATION s at 1/60 s in each engine with its catalogue defaults (`springcheck run`, a process
each, frames every second). Then, against backward Euler's last frame: the largest node distance
of each engine's last frame (mirror-aware: the fold settles to one of two mirror images across
the hanging plane z = 0, both equilibria), and how far each engine's own shape still moved over
its last second (the creep: a shape still moving is not settled, the reference's included).
Writes OUT_DIR/settle.csv and prints it. --compare-only: the runs already in OUT_DIR.
Plain Python (no numpy): reads the runs' trajectory.npy itself.
"""
import ast
import csv
import json
import math
import pathlib
import struct
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from scale_study import option, run, scene_at, write  # noqa: E402

DEFAULT_ENGINES = "mysim:backward-euler,mysim:local-global,mysim:xpbd,mysim:vbd"
DT = 1.0 / 60.0


def frames(folder):
    """(times, frames) of a run: each frame a list of (x, y, z) per node, from the .npy files."""
    def load(path):
        data = path.read_bytes()
        header_len = struct.unpack("<H", data[8:10])[0]
        header = ast.literal_eval(data[10:10 + header_len].decode("latin1"))
        assert header["descr"] == "<f8" and not header["fortran_order"], path
        values = struct.unpack(f"<{math.prod(header['shape'])}d", data[10 + header_len:])
        return header["shape"], values
    _, times = load(folder / "times.npy")
    shape, values = load(folder / "trajectory.npy")
    count, nodes, width = shape
    return list(times), [[values[(f * nodes + p) * width:(f * nodes + p) * width + 3]
                          for p in range(nodes)] for f in range(count)]


def largest_distance(a, b):
    """The largest node distance between two shapes, the nearer of b and its mirror in z."""
    direct = max(math.dist(p, q) for p, q in zip(a, b))
    mirrored = max(math.dist(p, (q[0], q[1], -q[2])) for p, q in zip(a, b))
    return min(direct, mirrored)


def compare(out, engines):
    runs = {}
    for engine in engines:
        folder = out / engine.replace(":", "_")
        if (folder / "summary.json").exists():
            runs[engine] = (json.loads((folder / "summary.json").read_text()), *frames(folder))
    reference = runs.get("mysim:backward-euler")
    rows = []
    for engine, (summary, times, shapes) in runs.items():
        last = shapes[-1]
        second_before = min(range(len(times)), key=lambda k: abs(times[k] - (times[-1] - 1.0)))
        rows.append({
            "engine": engine, "status": summary["status"],
            "blowup": (summary["blowup"] or {}).get("time", ""),
            "end_time": times[-1], "steps": summary["accepted_steps"],
            "rejected_steps": summary["rejected_steps"], "passes": summary["linear_iterations"],
            "wall_seconds": summary["wall_seconds"],
            "creep_last_second_mm": 1e3 * largest_distance(shapes[second_before], last),
            "settled_vs_backward_euler_mm":
                1e3 * largest_distance(last, reference[2][-1]) if reference else "",
        })
    return rows


def main(args):
    springcheck, out = args[0], pathlib.Path(args[1])
    cells = int(option(args, "--cells", 128))
    duration = float(option(args, "--duration", 24.0))
    threads = int(option(args, "--threads", 1))
    engines = option(args, "--engines", DEFAULT_ENGINES).split(",")
    out.mkdir(parents=True, exist_ok=True)
    if "--compare-only" not in args:
        spec_path = pathlib.Path(__file__).parent / "scale_study.json"
        base = json.loads((spec_path.parent / json.loads(spec_path.read_text())["base_scene"])
                          .read_text())
        steps = round(duration / DT)
        scene = scene_at(base, cells, DT, steps, {})
        scene["name"] = f"check_cloth_{cells}"
        scene["output"] = {"sample_interval": 1.0}
        scene_path = out / f"check_cloth_{cells}.json"
        scene_path.write_text(json.dumps(scene, indent=1))
        for engine in engines:
            summary = run(springcheck, scene_path, engine, out / engine.replace(":", "_"), threads)
            print(f"{engine}: {summary['status'] if summary else 'no summary'}", flush=True)
    rows = compare(out, engines)
    if not rows:
        sys.exit(f"settle_study.py: no runs in {out}")
    write(out / "settle.csv", rows)
    for row in rows:
        print(", ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}"
                        for k, v in row.items()))


if __name__ == "__main__":
    main(sys.argv[1:])
