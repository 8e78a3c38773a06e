#!/usr/bin/env python3
"""Cost per step and peak memory of each solver family as the cloth grows (issue 36, scale).

Usage: scale_study.py SPRINGCHECK SPEC OUT_DIR [--resolutions 64,128] [--steps N]
                      [--engines E1,E2] (engine names hold no comma) [--threads N]

For every resolution of SPEC (bench/scale_study.json) and every engine, writes the cloth scene
at that resolution and runs `springcheck run` on one thread twice, in processes of their own:
one step and `steps` steps (--threads: on N threads instead). The difference is the cost of a
step without the first step's set-up (a factorisation, a colouring), and the longer run's peak
resident memory, less a tiny scene's process (the executable and its libraries), is what the
cloth costs in memory. Writes OUT_DIR/scale.csv (a row per engine and resolution) and
OUT_DIR/scale_fit.csv (per engine: the growth exponent p of cost ~ nodes^p over all resolutions
and between each pair, and the largest memory per node), and prints both. Reads the runs'
summaries; no physics here.
"""
import csv
import json
import math
import pathlib
import shutil
import subprocess
import sys


def scene_at(base, n, dt, steps, integrator_fields):
    """The base cloth at n x n nodes, same total mass and drag rate (mass and drag per node scale
    as 1 / n^2), `steps` steps of dt, its start and end the only frames kept; the spec's
    integrator fields (backward Euler's cg_tolerance, which no engine name carries) added."""
    scene = json.loads(json.dumps(base))
    total_mass = base["system"]["particle_mass"] * base["system"]["rows"] * base["system"]["cols"]
    drag_rate = base["forces"]["drag"] / base["system"]["particle_mass"]
    scene["name"] = f"scale_{n}"
    scene["description"] = (f"{base['name']} at {n} x {n} nodes, same total mass, stiffnesses and "
                            f"drag rate: bench/scale_study.py")
    scene["system"]["rows"] = scene["system"]["cols"] = n
    scene["system"]["particle_mass"] = total_mass / (n * n)
    scene["forces"]["drag"] = drag_rate * total_mass / (n * n)
    scene["integrator"] = {"name": base["integrator"]["name"], "dt": dt, "duration": steps * dt,
                           **integrator_fields}
    scene["output"] = {"sample_interval": steps * dt}
    return scene


def run(springcheck, scene_path, engine, out, threads=1):
    """One `springcheck run` in its own process; its summary, or None with the reason printed.
    A run that ends unconverged or early still writes a whole summary, which says so (status)."""
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([springcheck, "run", str(scene_path), "--engine", engine, "--threads",
                           str(threads), "--fixed-threads", "--out", str(out)],
                          capture_output=True, text=True)
    if not (out / "summary.json").exists():
        print(f"{engine} on {scene_path.name}: exit {done.returncode}: {done.stderr.strip()}",
              file=sys.stderr)
        return None
    return json.loads((out / "summary.json").read_text())


def write_scenes(spec, base, n, work):
    """The n x n cloth's two scene files, one step and `steps` steps: {steps: path}."""
    paths = {}
    for steps in (1, spec["steps"]):
        paths[steps] = work / f"cloth_{n}_{steps}.json"
        paths[steps].write_text(json.dumps(scene_at(base, n, spec["dt"], steps,
                                                    spec.get("integrator_fields", {}))))
    return paths


def measure(springcheck, spec, scenes, n, engine, work, baseline_bytes, threads):
    """One row: the engine on the n x n cloth (its scene files `scenes`, from write_scenes)."""
    summaries = {}
    for steps, path in scenes.items():
        summaries[steps] = run(springcheck, path, engine, work / f"{engine}_{n}_{steps}", threads)
        if summaries[steps] is None:
            return None
    one, many = summaries[1], summaries[spec["steps"]]
    # A set-up the engine reports (local/global's factorisation) is taken out of each run first:
    # its own spread from run to run is larger than a step.
    stepping = [r["wall_seconds"] - (r.get("setup_seconds") or 0.0) for r in (one, many)]
    per_step = (stepping[1] - stepping[0]) / (spec["steps"] - 1)
    later_passes = (many["linear_iterations"] - one["linear_iterations"]) / (spec["steps"] - 1)
    nodes = n * n
    memory = many["peak_resident_bytes"] - baseline_bytes
    return {
        "engine": engine, "cells": n, "nodes": nodes, "threads": threads,
        "status": many["status"],
        "ms_per_step": 1e3 * per_step,
        # The one-step run less a step: the set-up, whether the engine reports it or not.
        "setup_ms": 1e3 * max(0.0, one["wall_seconds"] - per_step),
        "passes_per_step": later_passes,
        "us_per_pass_per_knode": 1e6 * per_step / max(later_passes, 1) / (nodes / 1e3),
        "solver_failures": many["solver_failures"],
        "peak_mib": memory / 2**20, "bytes_per_node": memory / nodes,
    }


def slope(points):
    """Least-squares slope of log(cost) on log(nodes)."""
    xs = [math.log(x) for x, _ in points]
    ys = [math.log(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else float("nan")


def fits(rows):
    """Per engine: the exponent over all sizes, between each pair of sizes, and memory's worst."""
    out = []
    for engine in dict.fromkeys(r["engine"] for r in rows):
        mine = [r for r in rows if r["engine"] == engine and r["ms_per_step"] > 0]
        if len(mine) < 2:
            continue
        points = [(r["nodes"], r["ms_per_step"]) for r in mine]
        local = [f"{a['cells']}-{b['cells']}: {slope(points[k:k + 2]):.2f}"
                 for k, (a, b) in enumerate(zip(mine, mine[1:]))]
        out.append({"engine": engine, "exponent": slope(points),
                    "pass_exponent": slope([(r["nodes"], r["us_per_pass_per_knode"] * r["nodes"])
                                            for r in mine]),
                    "between_sizes": "; ".join(local),
                    "worst_bytes_per_node": max(r["bytes_per_node"] for r in mine)})
    return out


def write(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def option(args, name, default):
    return args[args.index(name) + 1] if name in args else default


def main(args):
    springcheck, spec_path, out = args[0], pathlib.Path(args[1]), pathlib.Path(args[2])
    spec = json.loads(spec_path.read_text())
    spec["base"] = spec_path.parent / spec["base_scene"]
    spec["steps"] = int(option(args, "--steps", spec["steps"]))
    resolutions = [int(n) for n in option(args, "--resolutions",
                                          ",".join(map(str, spec["resolutions"]))).split(",")]
    engines = option(args, "--engines", ",".join(spec["engines"])).split(",")
    threads = int(option(args, "--threads", 1))
    work = out / "runs"
    work.mkdir(parents=True, exist_ok=True)
    baseline = run(springcheck, spec_path.parent / spec["baseline_scene"], "mysim",
                   work / "baseline")
    base = json.loads(spec["base"].read_text())
    rows = []
    for n in resolutions:
        scenes = write_scenes(spec, base, n, work)
        for engine in engines:
            row = measure(springcheck, spec, scenes, n, engine, work,
                          baseline["peak_resident_bytes"], threads)
            if row:
                rows.append(row)
                print(", ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}"
                                for k, v in row.items()), flush=True)
    if not rows:
        return 1
    write(out / "scale.csv", rows)
    fitted = fits(rows)
    if fitted:
        write(out / "scale_fit.csv", fitted)
        for f in fitted:
            print(f"{f['engine']}: cost ~ nodes^{f['exponent']:.2f} (a pass ~ nodes^"
                  f"{f['pass_exponent']:.2f}; {f['between_sizes']}); at most "
                  f"{f['worst_bytes_per_node']:.0f} B a node")
    return 0


if __name__ == "__main__":
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1:]))
