"""Speed against accuracy, and convergence, from the sweep tables."""
import json
import math
import os
from collections import defaultdict

import numpy as np

from report_style import Page, coincident, draw_coincidences, number, plot_area, read_csv, window_text, wrap_setup


def series_key(row):
    integrator = "" if row["integrator"] in ("-", "") else row["integrator"]
    return f"mysim:{integrator}" if row["engine"] == "mysim" else row["engine"]


def label_of(row):
    tolerance = row.get("tolerance") or ""
    return series_key(row) + (f" tol {tolerance}" if tolerance else "")


def draw_series(ax, series, variants, ctx, loglog=True):
    """One line per label; coinciding series redrawn hollow and named on the axes."""
    def style(label):
        pts = series[label]
        kw = ctx.styles.line(variants[label][0], variants[label][1])
        return [p[0] for p in pts], [p[1] for p in pts], kw
    for label in sorted(series):
        xs, ys, kw = style(label)
        (ax.loglog if loglog else ax.plot)(xs, ys, label=label, **kw)
    return draw_coincidences(ax, coincident(series), style)


def legend_outside(fig, ax):
    """One legend right of the plots (the last panel's entries: every panel has the same series)."""
    for old in fig.legends:
        old.remove()
    handles, labels = ax.get_legend_handles_labels()
    labels = [wrap_setup(label, 24) for label in labels]  # a long setup on lines that stay on the page
    fig.legend(handles, labels, loc="upper left", bbox_to_anchor=(0.81, 0.88), fontsize=7.5,
               frameon=False)


def pareto(points):
    """Points (time, error) not beaten on both: sorted by time, error strictly falling."""
    front, best = [], math.inf
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


def style_key(row):
    """The series' style: mysim's integrator without its parameters ('mysim:xpbd' for
    'mysim:xpbd:substeps=10'), so a method keeps its colour and its settings take line styles."""
    return ":".join(series_key(row).split(":")[:2])


def step_of(rows, x_column):
    """label -> {(x, error): dt}: each point's step, to label it."""
    steps = defaultdict(dict)
    for r in rows:
        x, e = number(r[x_column]), number(r["error"])
        if r["status"] == "ok" and x and e:
            steps[label_of(r)][(x, e)] = number(r["dt"])
    return steps


def label_steps(ax, series, steps):
    """Each series' first and last point marked with its step, so a point says which run it is."""
    for label, pts in series.items():
        for x, e in {pts[0], pts[-1]}:
            dt = steps[label].get((x, e))
            if dt:
                ax.annotate(f"{dt * 1e3:.3g} ms", (x, e), xytext=(3, 3), textcoords="offset points",
                            fontsize=6.5, color="0.3")


# The evidence rule for an order drawn from a sweep over the step (as refine's for resolutions,
# compare/studies/refinement.h): four steps or more; a sweep's table carries no expected order to
# hold three to. A slope under 0.5 is no convergence at all, said in words, not as an order.
MIN_STEPS_FOR_ORDER = 4
CONVERGING_SLOPE = 0.5


def evidenced_order(pts):
    """The observed order where the series has the evidence for one, else None."""
    order = fitted_order(pts) if len(pts) >= MIN_STEPS_FOR_ORDER else None
    return order if order is not None and order >= CONVERGING_SLOPE else None


def fitted_order(pts):
    """The least-squares slope of log error over log step: the observed order of convergence."""
    if len(pts) < 2:
        return None
    h, e = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return float(np.polyfit(h, e, 1)[0])


def collect(rows, x_column):
    """label -> sorted points, and label -> (style key, variant): a method's variants (dopri5's
    tolerances from the loosest, then parameter settings by name) take line styles in turn."""
    series, variants = defaultdict(list), {}
    labels = defaultdict(set)
    for r in rows:
        labels[style_key(r)].add((-(number(r.get("tolerance")) or 0), label_of(r)))
    order = {key: [label for _, label in sorted(v)] for key, v in labels.items()}
    for r in rows:
        x, e = number(r[x_column]), number(r["error"])
        if r["status"] == "ok" and x and e:
            key = style_key(r)
            series[label_of(r)].append((x, e))
            variants[label_of(r)] = (key, order[key].index(label_of(r)))
    for pts in series.values():
        pts.sort()
    return series, variants


def draw_precision_floors(ax, rows):
    """A float32 engine's precision floor (the sweep's precision_floor column) as a dotted line:
    below it an error is that engine's round-off, not integration error."""
    floors = defaultdict(float)
    for r in rows:
        if number(r.get("precision_floor")):
            floors[label_of(r)] = max(floors[label_of(r)], number(r["precision_floor"]))
    for label, floor in sorted(floors.items()):
        ax.axhline(floor, ls=":", color="black", lw=1.2, label=f"float32 floor of {label}")


def speed_title(sweep, recommendation):
    """The answer: the cheapest run under the recommendation's bound, per scene (at most two)."""
    if not recommendation:
        return f"Which engine and step reach a given error soonest? ({sweep['name']})"
    with open(recommendation["path"]) as f:
        rec = json.load(f)
    parts = []
    for r in rec["recommendations"][:2]:
        scene = os.path.basename(r["scene"]).removesuffix(".json") + f" x{r['stiffness_scale']:g}"
        best = r.get("best")
        if best:
            how = best["engine"] + (f" {best['integrator']}" if best.get("integrator", "-") != "-" else "")
            parts.append(f"{scene}: {how} at {best['dt'] * 1e3:.3g} ms ({best['realtime_factor']:.3g}x realtime)")
        else:
            parts.append(f"{scene}: no run")
    more = f"; {len(rec['recommendations']) - 2} more scenes" if len(rec["recommendations"]) > 2 else ""
    return (f"Cheapest under {rec['max_error'] * 1e3:g} mm {window_text(sweep)}: " + "; ".join(parts) + more)


def speed_accuracy_page(sweep, bounds, recommendation=None):
    def draw(fig, ctx):
        rows = read_csv(sweep["path"])
        # One panel per scene and stiffness: runs of different scenes never share a line.
        panels = sorted({(r["scene"], number(r["stiffness_scale"])) for r in rows},
                        key=lambda p: ([r["scene"] for r in rows].index(p[0]), p[1]))
        several_scenes = len({scene for scene, _ in panels}) > 1
        grid = plot_area(fig, 1, len(panels), right=0.8, wspace=0.25)
        notes, blown = [], defaultdict(set)
        for i, (scene, scale) in enumerate(panels):
            ax = fig.add_subplot(grid[0, i])
            part = [r for r in rows if r["scene"] == scene and number(r["stiffness_scale"]) == scale]
            name = (os.path.basename(scene) + ", " if several_scenes else "") + f"stiffness x{scale:g}"
            for r in part:
                if r["status"] != "ok":
                    blown[name].add(label_of(r))
            series, variants = collect(part, "wall_seconds")
            if not series:
                ax.text(0.5, 0.5, "no run finished", ha="center", transform=ax.transAxes)
                continue
            notes += draw_series(ax, series, variants, ctx)
            draw_precision_floors(ax, part)
            label_steps(ax, series, step_of(part, "wall_seconds"))
            for k, bound in enumerate(sorted(bounds)):
                ax.axhline(bound, color="#b00000", ls=("--", ":")[k % 2], lw=1.1,
                           label=f"target {bound:g} m")
            front = pareto([p for pts in series.values() for p in pts])
            ax.step(*zip(*front), where="post", color="black", lw=2.2, alpha=0.5, label="Pareto front")
            ax.set_xlabel("wall time of the stepping, fastest of the repeats [s]")
            ax.set_ylabel("error against the reference [m]")
            ax.set_title(name + (f"  ({len(blown[name])} series lost runs)" if blown[name] else ""),
                         fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            legend_outside(fig, ax)
        lost = [f"{n}: {', '.join(sorted(b))}" for n, b in blown.items() if b]
        return notes + ([f"Runs that blew up or hit a limit are left out ({'; '.join(lost)})."] if lost else [])
    reference = "the converged reference named in the table"
    return Page(f"speed_accuracy_{sweep['name']}", speed_title(sweep, recommendation),
                f"Each point is one run of the sweep: its error against {reference} (max over frames of "
                f"the RMS node distance, {window_text(sweep)}) against the wall time of its stepping. Lower left is better; the "
                "grey staircase is the Pareto front, the runs no other run beats on both. Points on one "
                "line are one engine or integrator at different steps (its first and last labelled with the "
                "step); the red dashed lines are the error bounds the recommendation is asked for.", draw)


def place_order_labels(ax, orders):
    """Writes each order left of its series' finest point, moved apart vertically where series
    end close together (labels never overlap): at least 1/25 of the axis' decades between them."""
    if not orders:
        return
    ax.relim()
    ax.autoscale_view()
    low, high = (math.log10(v) for v in ax.get_ylim())
    gap = (high - low) / 25
    placed = []
    for (x, y), text, colour in sorted(orders, key=lambda o: o[0][1]):
        at = max(math.log10(y), placed[-1] + gap) if placed else math.log10(y)
        placed.append(at)
        ax.annotate(text, (x, 10 ** at), xytext=(-4, 0), textcoords="offset points", ha="right", va="center",
                    fontsize=7, color=colour)


def convergence_title(sweep):
    """The answer: each series' observed order on the sweep's first scene, highest first."""
    rows = read_csv(sweep["path"])
    if not rows:
        return f"Does each method converge at its order? ({sweep['name']})"
    scale = min(number(r["stiffness_scale"]) for r in rows)
    first = rows[0]["scene"]
    series, _ = collect([r for r in rows if r["scene"] == first and number(r["stiffness_scale"]) == scale], "dt")
    orders = sorted(((evidenced_order(pts), label.removeprefix("mysim:")) for label, pts in series.items()
                     if evidenced_order(pts) is not None), reverse=True)
    if not orders:
        return (f"Does each method converge at its order? ({sweep['name']}: no series with "
                f"{MIN_STEPS_FOR_ORDER} finished steps, so no order is drawn)")
    scene = os.path.basename(first).removesuffix(".json")
    title = f"Observed orders on {scene} {window_text(sweep)}: " + ", ".join(f"{n} {o:.2f}" for o, n in orders)
    if len(title) <= 200:
        return title
    # Too many series to name in a title: the span, the highest and the lowest (each line says its own).
    return (f"Observed orders on {scene} {window_text(sweep)}: {orders[-1][0]:.2f} ({orders[-1][1]}) to "
            f"{orders[0][0]:.2f} ({orders[0][1]}) over {len(orders)} series, each written at its finest step")


def draw_orders(ax, ctx, name, scene, series, variants):
    """Each series' observed order at its finest step where it has the evidence (each one a claim
    the report's check holds to the rule), "flat" where it does not converge; returns the notes."""
    orders, short, flat = [], [], []
    for label, pts in sorted(series.items()):
        colour = ctx.styles.line(*variants[label])["color"]
        order = evidenced_order(pts)
        if len(pts) < MIN_STEPS_FOR_ORDER:
            short.append(label)
        elif order is None:
            flat.append(label)
            orders.append((pts[0], "flat", colour))
        else:
            orders.append((pts[0], f"{order:.2f}", colour))
            ctx.claims.append({"page": f"convergence_{name}", "kind": "order", "engine": label,
                               "quantity": f"error over the step ({os.path.basename(scene)})",
                               "resolutions": " ".join(f"{p[0]:g}" for p in pts), "observed_order": f"{order}",
                               "expected_order": "", "verdict": f"converged: observed order {order:.2f} "
                                                                f"from {len(pts)} steps"})
    place_order_labels(ax, orders)
    notes = [f"No order drawn for {', '.join(short)}: fewer than {MIN_STEPS_FOR_ORDER} finished steps."] if short else []
    return notes + ([f"'flat': {', '.join(flat)} do not converge over these steps (slope under "
                     f"{CONVERGING_SLOPE})."] if flat else [])


def convergence_page(sweep):
    def draw(fig, ctx):
        rows = read_csv(sweep["path"])
        scale = min(number(r["stiffness_scale"]) for r in rows)
        rows = [r for r in rows if number(r["stiffness_scale"]) == scale]
        scenes = list(dict.fromkeys(r["scene"] for r in rows))  # one panel each, in table order
        grid = plot_area(fig, 1, len(scenes), right=0.8, wspace=0.25)
        notes = []
        for i, scene in enumerate(scenes):
            ax = fig.add_subplot(grid[0, i])
            part = [r for r in rows if r["scene"] == scene]
            series, variants = collect(part, "dt")
            if not series:
                ax.text(0.5, 0.5, "no run finished", ha="center", transform=ax.transAxes)
                continue
            notes += draw_series(ax, series, variants, ctx)
            draw_precision_floors(ax, part)
            notes += draw_orders(ax, ctx, sweep["name"], scene, series, variants)
            ax.set_xlabel("step dt [s]")
            refs = sorted({r["reference"] for r in part if r.get("reference")})
            ax.set_ylabel(f"error against {', '.join(refs) or 'the reference'} [m]")
            if len(scenes) > 1:
                ax.set_title(os.path.basename(scene), fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            legend_outside(fig, ax)
        return notes
    against = ("each engine against itself at a finer step (self-consistency), so Bullet is measured "
               "against Bullet" if sweep["self_reference"] else "one converged reference run")
    return Page(f"convergence_{sweep['name']}", convergence_title(sweep),
                f"Error of every finished run against {against} ({window_text(sweep)}), over the step, "
                "log-log, at the sweep's lowest stiffness. The number left of each line's finest step is its observed order of "
                "convergence, the least-squares slope of log error over log step, drawn only from four finished "
                "steps or more (1 for Euler-type schemes, "
                "2 for Verlet and Heun, 4 for RK4 is the theory); a line that flattens has hit the error of "
                "its reference or its solver tolerance, and its fitted order then reads low.", draw)


def pages(manifest):
    sweeps = manifest["sweeps"]
    shared = [s for s in sweeps if not s["self_reference"]]
    # Per sweep, the error bounds its recommendations were asked for.
    bounds = defaultdict(set)
    for b in manifest.get("recommendation_bounds") or []:
        bounds[b["sweep"]].add(b["max_error"])
    recommendations = {r["sweep"]: r for r in manifest.get("recommendations", [])}
    return [speed_accuracy_page(s, bounds[s["name"]], recommendations.get(s["name"])) for s in shared] + \
        [convergence_page(s) for s in sweeps]
