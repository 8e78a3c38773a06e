#!/usr/bin/env python3
"""Builds the springcheck report (report.pdf and one PNG per figure) from result tables.

The C++ side writes every number; this script only reads tables and draws them (and picks the
fastest row under an error bound, which is a lookup, not physics). Inputs, under --results:

  gate.json                          springcheck gate --json
  sweep/*.csv                        springcheck sweep (chain_convergence.csv, cloth_speed_accuracy.csv)
  stability/stability.csv            springcheck stability
  stability/extremes.csv             springcheck stability --extremes
  energy/<scene>/series.csv          springcheck compare, one engine per integrator
  suite/cloth_hanging/...            springcheck suite (final_state.csv, final.obj, node_distance.csv, series.csv)
  suite/cloth_on_sphere/series.csv
  bench/bench.json                   scripts/run-bench.sh (optional: adds a performance page)

Run with the interpreter that has matplotlib (CMake finds it; `springcheck report` uses it).
"""
import argparse
import csv
import json
import math
import os
import sys
import textwrap
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.backends.backend_pdf import PdfPages  # noqa: E402



def read_csv(path):
    if not os.path.exists(path):
        sys.exit(f"make_report: missing input {path}")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def label_of(row):
    label = row["engine"] if row["integrator"] in ("-", "") else f"{row['engine']}:{row['integrator']}"
    return label + (f" tol {row['tolerance']}" if row.get("tolerance") else "")


def style_cycle():
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    markers = "osD^v<>ph*"
    i = 0
    while True:
        # markers shift on each pass through the colours: no two series look alike
        yield colours[i % len(colours)], markers[(i + i // len(colours)) % len(markers)]
        i += 1


def pareto(points):
    """Points (time, error) not beaten on both: sorted by time, error strictly falling."""
    front, best = [], math.inf
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def figure_summary(results, sweeps, stability, extremes):
    fig = plt.figure(figsize=(8.27, 11.69))
    fig.text(0.5, 0.96, "springcheck report", ha="center", fontsize=18, weight="bold")
    lines = []
    # The answer first: `springcheck recommend` on each sweep (the main job writes recommend/).
    rec_dir = os.path.join(results, "recommend")
    recs = sorted(f for f in os.listdir(rec_dir) if f.endswith(".json")) if os.path.isdir(rec_dir) else []
    for f in recs:
        rec = json.load(open(os.path.join(rec_dir, f)))
        lines.append(f"Recommended ({os.path.splitext(f)[0]}): cheapest by {rec['cost'].replace('_', ' ')} "
                     f"with error <= {rec['max_error']:g} m")
        for r in rec["recommendations"]:
            lines.append(f"  {os.path.basename(r['scene'])}, stiffness x{r['stiffness_scale']:g} "
                         f"({r['meeting']} of {r['candidates']} finished runs meet it):")
            if r["best"]:
                for tag, c in (("best", r["best"]), ("runner-up", r["runner_up"])):
                    if c:
                        lines.extend(textwrap.wrap(f"{tag}: {c['summary']}", 96,
                                                   initial_indent="    ", subsequent_indent="      "))
            else:
                lines.append("    none stays under the bound")
    if recs:
        lines.append("")
    gate = json.load(open(os.path.join(results, "gate.json")))
    checks = gate["checks"]
    passed = sum(c["passed"] for c in checks)
    lines.append(f"Tolerance gates: {passed} of {len(checks)} passed ({gate['tolerances']})")
    for c in checks:
        if not c["passed"]:
            lines.append(f"  FAILED {os.path.basename(c['scene'])} {c['metric']} {' ~ '.join(c['engines'])}: "
                         f"{c['measured']} > {c['bound']} {c['problem']}")
    interesting = [c for c in checks if c["metric"] in ("drape_max", "closed_form_error", "penetration_max")]
    for c in interesting[:10]:
        measured = "n/a" if c["measured"] is None else f"{c['measured']:.3g}"
        lines.append(f"  {os.path.basename(c['scene']):22s} {c['metric']:18s} {' ~ '.join(c['engines']):40s} {measured}")
    lines.append("")
    # Momentum: the free-floating scenes of the suite, where nothing outside acts.
    suite_dir = os.path.join(results, "suite")
    for scene in sorted(os.listdir(suite_dir)) if os.path.isdir(suite_dir) else []:
        path = os.path.join(suite_dir, scene, "comparison.json")
        if not os.path.exists(path):
            continue
        engines = [e for e in json.load(open(path))["engines"] if e.get("linear_momentum_drift") is not None]
        if engines:
            lines.append(f"Momentum drift on {scene} (free body; relative, max over the run):")
            for e in engines:
                lines.append(f"  {e['engine']:24s} linear {e['linear_momentum_drift']:9.2g}   "
                             f"angular {e['angular_momentum_drift']:9.2g}")
    lines.append("")
    for name, rows in sweeps.items():
        lines.append(f"Sweep {name}: {len(rows)} runs, {sum(r['status'] == 'blowup' for r in rows)} blew up")
        blown = sorted({(label_of(r), r["dt"], r["stiffness_scale"]) for r in rows if r["status"] == "blowup"})
        for lab, dt, scale in blown[:8]:
            lines.append(f"  blew up: {lab} at dt {dt} s, stiffness x{scale}")
    lines.append("")
    lines.append("Largest stable step on the oscillator, as h w (theory in brackets):")
    by_method = defaultdict(list)
    for r in stability:
        if r["status"] == "bracketed":
            by_method[r["integrator"]].append(number(r["h_stable"]) * number(r["omega"]))
        elif r["status"] == "stable-at-max":
            by_method[r["integrator"]].append(math.inf)
    theory = {"symplectic-euler": "2", "verlet": "2", "rk4": "2.83", "euler": "2 zeta",
              "backward-euler": "inf", "trapezoidal": "none"}
    for method, values in by_method.items():
        finite = [v for v in values if math.isfinite(v)]
        shown = f"{np.median(finite):.3g}" if finite else f">= {100:g} (all steps tried)"
        lines.append(f"  {method:18s} {shown:>24s}   [{theory.get(method, '?')}]")
    lines.append("")
    lines.append("At the extremes:")
    for r in extremes:
        lines.append(f"  {r['case']:32s} {r['integrator']:18s} {r['quantity']:24s} {number(r['value']):.4g} {r['unit']}")
    fig.text(0.06, 0.92, "\n".join(lines), va="top", family="monospace", fontsize=6.6)
    return fig


def figure_speed_accuracy(sweeps):
    fig, axes = plt.subplots(1, len(sweeps), figsize=(6 * len(sweeps), 5), squeeze=False)
    for ax, (name, rows) in zip(axes[0], sweeps.items()):
        rows = [r for r in rows if number(r["stiffness_scale"]) == 1.0 and r["status"] == "ok"
                and number(r["error"]) and number(r["wall_seconds"])]
        series = defaultdict(list)
        for r in rows:
            series[label_of(r)].append((number(r["wall_seconds"]), number(r["error"])))
        styles = style_cycle()
        for lab, pts in sorted(series.items()):
            colour, marker = next(styles)
            pts.sort()
            ax.loglog(*zip(*pts), marker=marker, color=colour, label=lab, lw=1)
        front = pareto([p for pts in series.values() for p in pts])
        ax.step(*zip(*front), where="post", color="black", lw=2, alpha=0.6, label="Pareto front")
        ax.set_xlabel("wall time of the stepping [s]")
        ax.set_ylabel("error vs converged run (max RMS node distance) [m]")
        ax.set_title(f"speed / accuracy: {name}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def figure_convergence(rows, name):
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    series = defaultdict(list)
    for r in rows:
        if r["status"] == "ok" and number(r["error"]):
            series[label_of(r)].append((number(r["dt"]), number(r["error"])))
    styles = style_cycle()
    for lab, pts in sorted(series.items()):
        colour, marker = next(styles)
        pts.sort()
        ax.loglog(*zip(*pts), marker=marker, color=colour, label=lab)
    dts = sorted({p[0] for pts in series.values() for p in pts})
    errors = [p[1] for pts in series.values() for p in pts]
    anchor = math.exp(np.mean(np.log(errors)))
    h = np.array([dts[0], dts[-1]])
    for order, style in ((1, ":"), (2, "--"), (4, "-.")):
        ax.loglog(h, anchor * (h / h[-1]) ** order, style, color="grey", lw=1.2, label=f"slope {order}")
    ax.set_xlabel("step dt [s]")
    refs = sorted({r["reference"] for r in rows if r.get("reference")})
    ax.set_ylabel(f"error vs {', '.join(refs) or 'reference'} (max RMS node distance) [m]")
    ax.set_title(f"convergence: {name}" + (" (each engine against itself)" if any(x.startswith("self") for x in refs) else ""))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    return fig


def figure_stability(rows):
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    masses = sorted({number(r["mass"]) for r in rows})
    mass = masses[len(masses) // 2]
    styles = style_cycle()
    for method in sorted({r["integrator"] for r in rows}):
        pts = sorted((number(r["stiffness"]), number(r["h_stable"]), r["status"], number(r["theory_h"]))
                     for r in rows if r["integrator"] == method and number(r["mass"]) == mass)
        colour, marker = next(styles)
        k = [p[0] for p in pts]
        measured = [p[1] for p in pts]
        capped = any(p[2] == "stable-at-max" for p in pts)
        ax.loglog(k, measured, marker=marker, color=colour,
                  label=method + (" (stable at every step tried)" if capped else ""))
        theory = [p[3] for p in pts]
        if all(t is not None and math.isfinite(t) and t > 0 for t in theory):
            ax.loglog(k, theory, "--", color=colour, lw=1, label=f"{method} theory")
    ax.set_xlabel("spring stiffness k [N/m]")
    ax.set_ylabel("largest stable step [s]")
    ax.set_title(f"stability map: oscillator, m = {mass:g} kg (dashed: theory)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    return fig


def figure_scene_stability(rows, scene):
    """Largest stable step of every engine against stiffness, one panel per neighbour mass ratio,
    with the theory line c / w_max of each scheme that has one (dashed)."""
    ratios = sorted({number(r["mass_ratio"]) for r in rows})
    fig, axes = plt.subplots(1, len(ratios), figsize=(5.2 * len(ratios), 5.2), squeeze=False)
    engines = sorted({(r["engine"], r["classic_iterations"]) for r in rows})
    handles = {}
    for ax, ratio in zip(axes[0], ratios):
        styles = style_cycle()
        theory_drawn = set()
        notes = []
        for engine in engines:
            pts = sorted((number(r["stiffness"]), r) for r in rows
                         if (r["engine"], r["classic_iterations"]) == engine and number(r["mass_ratio"]) == ratio)
            label = engine[0] + (f" ({engine[1]} passes)" if engine[1] else "")
            colour, marker = next(styles)
            shown = [(k, number(r["h_stable"])) for k, r in pts
                     if r["status"] in ("bracketed", "stable-at-max") and number(r["h_stable"])]
            if not shown:
                refused = any(r["status"] == "refused" for _, r in pts)
                notes.append(label + (": refuses this model" if refused else ": unstable at every step"))
                continue
            capped = any(r["status"] == "stable-at-max" for _, r in pts)
            line, = ax.loglog([p[0] for p in shown], [p[1] for p in shown], marker=marker, color=colour,
                              lw=1, label=label + (" (stable up to h w_max = 30)" if capped else ""))
            handles.setdefault(label, line)
            theory = [(k, number(r["theory_h"])) for k, r in pts]
            if all(t is not None and math.isfinite(t) and t > 0 for _, t in theory):
                key = round(theory[0][1] * number(pts[0][1]["w_max"]), 3)  # the constant c
                if key not in theory_drawn:
                    theory_drawn.add(key)
                    ax.loglog([t[0] for t in theory], [t[1] for t in theory], "--", color="0.3", lw=1)
                    ax.annotate(f"h w_max = {key:g}", (theory[-1][0], theory[-1][1]), fontsize=7,
                                xytext=(-60, 4), textcoords="offset points", color="0.3")
        ax.set_xlabel("spring stiffness k [N/m]")
        ax.set_title(f"neighbour mass ratio {ratio:g}")
        ax.grid(True, which="both", alpha=0.3)
        if notes:
            ax.text(0.02, 0.02, "\n".join(notes), transform=ax.transAxes, fontsize=7, va="bottom",
                    bbox=dict(facecolor="white", alpha=0.8, edgecolor="0.8"))
    axes[0][0].set_ylabel("largest stable step [s]")
    fig.legend(list(handles.values()), [h.get_label() for h in handles.values()], fontsize=7.5,
               loc="lower center", ncol=4, frameon=False)
    fig.suptitle(f"stability map: {scene}, every engine (dashed: theory c / w_max, w_max by Lanczos)")
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    return fig


def figure_energy(results):
    scenes = [("chain_swing", "undamped: chain_swing"), ("chain_hanging", "damped (drag): chain_hanging")]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, (scene, title) in zip(axes, scenes):
        rows = read_csv(os.path.join(results, "energy", scene, "series.csv"))
        series = defaultdict(list)
        for r in rows:
            if number(r["energy_drift_total"]) is not None:
                series[r["engine"]].append((number(r["t"]), number(r["energy_drift_total"])))
        styles = style_cycle()
        for engine, pts in sorted(series.items()):
            colour, _ = next(styles)
            ax.plot(*zip(*pts), color=colour, label=engine, lw=1.2)
        ax.set_xlabel("time t [s]")
        ax.set_ylabel("(E(t) - E(0)) / E_ref  [1]")
        ax.set_title(f"energy drift, {title}")
        ax.set_yscale("symlog", linthresh=1e-4)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def read_obj_faces(path):
    faces = []
    with open(path) as f:
        for line in f:
            if line.startswith("f "):
                faces.append([int(v.split("/")[0]) - 1 for v in line.split()[1:4]])
    return np.array(faces)


def figure_drape(results):
    base = os.path.join(results, "suite", "cloth_hanging")
    distances = defaultdict(dict)
    reference = None
    for r in read_csv(os.path.join(base, "node_distance.csv")):
        distances[r["engine"]][int(r["node"])] = number(r["distance"])
        reference = r["reference_engine"]
    engines = [reference] + sorted(distances)
    fig = plt.figure(figsize=(4.2 * len(engines), 5))
    vmax = max(max(d.values()) for d in distances.values())
    for i, engine in enumerate(engines):
        folder = os.path.join(base, engine.replace(":", "_"))
        state = read_csv(os.path.join(folder, "final_state.csv"))
        xyz = np.array([[number(r["x"]), number(r["y"]), number(r["z"])] for r in state])
        faces = read_obj_faces(os.path.join(folder, "final.obj"))
        ax = fig.add_subplot(1, len(engines), i + 1, projection="3d")
        ax.plot_trisurf(xyz[:, 0], xyz[:, 2], xyz[:, 1], triangles=faces, color="lightgrey",
                        alpha=0.5, edgecolor="grey", linewidth=0.2)
        d = np.array([distances[engine].get(n, 0.0) for n in range(len(xyz))]) if engine != reference \
            else np.zeros(len(xyz))
        sc = ax.scatter(xyz[:, 0], xyz[:, 2], xyz[:, 1], c=d, cmap="viridis", vmin=0, vmax=vmax, s=12)
        ax.set_title(engine + ("\n(reference)" if engine == reference else ""), fontsize=9)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
        ax.set_zlabel("y [m]")
    cbar = fig.colorbar(sc, ax=fig.axes, shrink=0.6, location="bottom")
    cbar.set_label(f"distance of each node to {reference}'s settled position [m]")
    fig.suptitle("settled drape: cloth_hanging")
    return fig


def plot_series(ax, path, column, scale, ylabel, title):
    """One line per engine of a series.csv column against time."""
    series = defaultdict(list)
    for r in read_csv(path):
        series[r["engine"]].append((number(r["t"]), scale * number(r[column])))
    for engine, pts in sorted(series.items()):
        ax.plot(*zip(*pts), label=engine, lw=1.2)
    ax.set_xlabel("time t [s]")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)


def figure_sag_penetration(results):
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    plot_series(axes[0], os.path.join(results, "suite", "cloth_hanging", "series.csv"), "sag_lowest", 1.0,
                "lowest point below the pins [m]", "sag over time: cloth_hanging")
    plot_series(axes[1], os.path.join(results, "suite", "cloth_on_sphere", "series.csv"), "penetration_deepest",
                1e3, "deepest node inside the sphere [mm]", "sphere penetration over time: cloth_on_sphere")
    fig.tight_layout()
    return fig


def figure_performance(bench_json):
    """Per-step cost of every integrator and Bullet engine, and force evaluation against size."""
    data = json.load(open(bench_json))
    median = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name", "median") == "median":
            median[b.get("run_name", b["name"]).replace("/real_time", "")] = b
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    names, times, colours = [], [], []
    for key, b in median.items():
        if key.startswith("BM_MysimStep/") or key.startswith("BM_BulletStep/"):
            names.append(key.split("/")[1])
            times.append(b["real_time"])
            colours.append("tab:blue" if key.startswith("BM_MysimStep/") else "tab:orange")
    axes[0].barh(names, times, color=colours)
    axes[0].set_xscale("log")
    axes[0].set_xlim(left=1)
    axes[0].set_xlabel("time per step, 32 x 32 cloth [us] (blue: mysim, orange: Bullet)")
    axes[0].set_title("one step, same scene and dt")
    axes[0].grid(True, axis="x", which="both", alpha=0.3)
    sizes, per = [], []
    for key, b in median.items():
        if key.startswith("BM_ClothForce/"):
            sizes.append(int(key.split("/")[1]) ** 2)
            per.append(b["ns_per_particle"])
    axes[1].loglog(sizes, per, "o-", label="measured (all cores)")
    bound = [b["bound_ns"] / n for n, b in zip(sizes, (median[f"BM_ClothForce/{int(math.sqrt(n))}"] for n in sizes))]
    axes[1].loglog(sizes, bound, "--", label="memory-bandwidth bound")
    axes[1].set_xlabel("particles")
    axes[1].set_ylabel("force evaluation per particle [ns]")
    axes[1].set_title("cloth force evaluation against the roofline")
    axes[1].grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default="out", help="directory holding the result tables")
    parser.add_argument("--out", default="out/report", help="where report.pdf and the PNGs go")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    sweep_dir = os.path.join(args.results, "sweep")
    sweeps = {os.path.splitext(f)[0]: read_csv(os.path.join(sweep_dir, f))
              for f in sorted(os.listdir(sweep_dir)) if f.endswith(".csv")} if os.path.isdir(sweep_dir) else {}
    if not sweeps:
        sys.exit(f"make_report: no sweep tables in {sweep_dir}")
    stability = read_csv(os.path.join(args.results, "stability", "stability.csv"))
    extremes = read_csv(os.path.join(args.results, "stability", "extremes.csv"))
    convergence_name = next((n for n in sweeps if "convergence" in n), next(iter(sweeps)))
    # Self-consistency sweeps measure each engine against itself: their own convergence page,
    # never on the speed/accuracy page, whose errors share one reference.
    self_sweeps = {n: rows for n, rows in sweeps.items()
                   if any(r.get("reference", "").startswith("self") for r in rows)}
    shared = {n: rows for n, rows in sweeps.items() if n not in self_sweeps} or sweeps

    figures = [
        ("01_summary", figure_summary(args.results, sweeps, stability, extremes)),
        ("02_speed_accuracy", figure_speed_accuracy(shared)),
        ("03_convergence", figure_convergence(sweeps[convergence_name], convergence_name)),
    ] + [(f"03_convergence_{n}", figure_convergence(rows, n)) for n, rows in self_sweeps.items()] + [
        ("04_stability_map", figure_stability(stability)),
        ("05_energy_drift", figure_energy(args.results)),
        ("06_drape", figure_drape(args.results)),
        ("07_sag_penetration", figure_sag_penetration(args.results)),
    ]
    stability_dir = os.path.join(args.results, "stability")
    maps = [f for f in sorted(os.listdir(stability_dir)) if f.startswith("stability_") and f.endswith(".csv")] \
        if os.path.isdir(stability_dir) else []
    for n, f in enumerate(maps):
        scene = f[len("stability_"):-len(".csv")]
        figures.insert(4 + n, (f"04_stability_map_{scene}",
                           figure_scene_stability(read_csv(os.path.join(stability_dir, f)), scene)))
    bench_json = os.path.join(args.results, "bench", "bench.json")
    if os.path.exists(bench_json):  # scripts/run-bench.sh was run: add its page
        figures.append(("08_performance", figure_performance(bench_json)))
    pdf_path = os.path.join(args.out, "report.pdf")
    with PdfPages(pdf_path) as pdf:
        for name, fig in figures:
            fig.savefig(os.path.join(args.out, name + ".png"), dpi=110)
            pdf.savefig(fig)
            plt.close(fig)
    print(f"report: {pdf_path} and {len(figures)} PNGs in {args.out}")


if __name__ == "__main__":
    main()
