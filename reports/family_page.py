"""Which solver family for this cloth at this error: each family's cheapest run under each bound
the sweep was recommended at (springcheck recommend's per_family and closest_per_family)."""
import json
import os

from report_style import Page, plot_area, window_text

BOUND_COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728"]


def metres(value):
    return f"{value * 1e3:.3g} mm" if value < 1 else f"{value:.3g} m"


def family_label(choice):
    """A family of mysim's catalogue says so; a Bullet (or the user's) engine is its own row."""
    return f"{choice['family']} (mysim)" if choice["engine"] == "mysim" else choice["family"]


def setting(choice):
    what = choice["engine"] if choice["integrator"] in ("-", "") else choice["integrator"]
    return f"{what}, dt 1/{1 / choice['dt']:.0f} s"


def family_title(sweep, bounds, window):
    """The answer: per scene, the cheapest family under the tightest bound any family meets."""
    parts = []
    for b in sorted(bounds, key=lambda b: b["max_error"]):
        with open(b["path"]) as f:
            for r in json.load(f)["recommendations"]:
                scene = os.path.basename(r["scene"]).removesuffix(".json")
                if r.get("best") and not any(p.startswith(scene + ":") for p in parts):
                    parts.append(f"{scene}: {family_label(r['best'])} under {metres(b['max_error'])}")
    if not parts:
        return f"No solver family meets the bounds ({sweep})"
    return f"Cheapest family {window}: " + "; ".join(parts)


def family_page(sweep, bounds, window):
    bounds = sorted(bounds, key=lambda b: -b["max_error"])  # the loosest first

    def draw(fig, ctx):
        files = [json.load(open(b["path"])) for b in bounds]
        scenes = [r["scene"] for r in files[0]["recommendations"]]
        grid = plot_area(fig, 1, len(scenes), left=0.13, top=0.85, wspace=0.55)
        notes = []
        for i, scene in enumerate(scenes):
            ax = fig.add_subplot(grid[0, i])
            per_bound = [next(r for r in f["recommendations"] if r["scene"] == scene) for f in files]
            closest = {family_label(c): c for c in per_bound[0]["closest_per_family"]}
            families = sorted(closest, key=lambda fam: closest[fam]["error"])
            height = 0.8 / len(bounds)
            best_rtf = max([c["realtime_factor"] for r in per_bound for c in r["per_family"]] + [1.0])
            for b, (bound, r) in enumerate(zip(bounds, per_bound)):
                met = {family_label(c): c for c in r["per_family"]}
                for y, fam in enumerate(families):
                    pos = y + (b - (len(bounds) - 1) / 2) * height
                    if fam in met:
                        c = met[fam]
                        ax.barh(pos, c["realtime_factor"], height=height * 0.9,
                                color=BOUND_COLOURS[b % len(BOUND_COLOURS)],
                                label=f"error <= {metres(bound['max_error'])}" if y == 0 else None)
                        ax.text(c["realtime_factor"] * 1.08, pos, f"{c['realtime_factor']:.3g}x: {setting(c)}",
                                va="center", fontsize=7)
                    else:
                        ax.text(1.05, pos, f"none <= {metres(bound['max_error'])} "
                                f"(its best: {metres(closest[fam]['error'])})", va="center", fontsize=7,
                                color="0.35", style="italic")
                if not any(True for _ in met):
                    notes.append(f"{os.path.basename(scene)}: no family meets {metres(bound['max_error'])}.")
            ax.axvline(1.0, color="0.5", lw=0.8, ls=":")
            ax.set_xscale("log")
            ax.set_xlim(1.0, best_rtf * 40)
            ax.set_yticks(range(len(families)), families, fontsize=8)
            ax.set_ylim(len(families) - 0.4, -0.6)  # the most accurate on top, room below the last
            ax.set_xlabel("realtime factor of the cheapest run under the bound (log)")
            ratios = [f"{metres(bd['max_error'])}: {r['mysim_over_bullet_realtime']:.3g}x"
                      for bd, r in zip(bounds, per_bound) if r.get("mysim_over_bullet_realtime")]
            ratio_line = ("\nmysim's best over Bullet's best: " + ", ".join(ratios)) if ratios else ""
            ax.set_title(os.path.basename(scene) + ratio_line, fontsize=9)
            ax.grid(True, axis="x", which="both", alpha=0.3)
            ax.legend(loc="lower right", fontsize=7, framealpha=0.95)
        return notes

    listed = " and ".join(metres(b["max_error"]) for b in bounds)
    return Page(f"solver_families_{sweep}", family_title(sweep, bounds, window),
                f"Each family's cheapest run whose error (max over frames of the RMS node distance to the "
                f"sweep's converged reference, {window}) stays under {listed}: the bar is its realtime factor, the "
                "label its setting. Families are mysim's integrator families of the catalogue and each Bullet "
                "engine; 'none' means no step of the sweep gets that family under the bound, with the "
                "smallest error it reached. Rows run from the most accurate family down. The dotted line "
                "is real time. Timings are this machine's (fastest of the sweep's repeats).", draw)


def pages(manifest):
    by_sweep = {}
    for b in manifest.get("recommendation_bounds", []):
        by_sweep.setdefault(b["sweep"], []).append(b)
    windows = {s["name"]: window_text(s) for s in manifest.get("sweeps", [])}
    return [family_page(sweep, bounds, windows.get(sweep, window_text(None)))
            for sweep, bounds in sorted(by_sweep.items()) if len(bounds) >= 2]
