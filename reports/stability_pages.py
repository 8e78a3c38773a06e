"""Where each engine and integrator goes unstable, against theory (the stability tables)."""
from collections import defaultdict

import numpy as np

from report_style import Page, number, plot_area, read_csv, wrap_setup

FOUND = ("bracketed", "stable-at-max")


def oscillator_title(rows):
    """The answer: how close the schemes with a theory come to it, and which never went unstable."""
    ratios = defaultdict(list)
    stable = set()
    for r in rows:
        if r["status"] == "bracketed" and number(r["ratio"]):
            ratios[r["integrator"]].append(number(r["ratio"]))
        elif r["status"] == "stable-at-max":
            stable.add(r["integrator"])
    if not ratios:
        return "How close does each integrator come to its theoretical step limit?"
    low = min(ratios, key=lambda n: min(ratios[n]))
    high = max(ratios, key=lambda n: max(ratios[n]))
    text = (f"Oscillator: limits at x{min(ratios[low]):.2f} ({integrator_label(low)}) to "
            f"x{max(ratios[high]):.2f} ({integrator_label(high)}) of theory")
    return text + (f"; {len(stable)} stable at every step tried" if stable else "")


def oscillator_series(ratio_ax, map_ax, key, mine, kw):
    """One integrator: its measured / theory where it has a theory, its map (a line through the
    limits found, hollow markers where stable at the largest step tried), its theory dashed;
    returns what to say of it when it has no theory."""
    ratios = [(k, number(r["ratio"])) for k, r in mine if r["status"] == "bracketed" and number(r["ratio"])]
    if ratios:
        ratio_ax.semilogx(*zip(*ratios), label=key, **kw)
    draw_map_series(map_ax, mine, key, kw)
    if ratios:
        return None
    hw = [number(r["h_stable"]) * number(r["omega"]) for _, r in mine if r["status"] == "bracketed"]
    capped = any(r["status"] == "stable-at-max" for _, r in mine)
    return f"{key}: " + ("stable at every step tried" if capped else
                         f"limit h w = {np.median(hw):.3g}, no theory" if hw else "no stable step")


def oscillator_page(path):
    rows = read_csv(path)

    def draw(fig, ctx):
        masses = sorted({number(r["mass"]) for r in rows})
        mass = masses[len(masses) // 2]
        grid = plot_area(fig, 1, 2, right=0.8, wspace=0.28)
        ratio_ax, map_ax = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
        untheorised = []
        for method in sorted({r["integrator"] for r in rows}):
            key = f"mysim:{method}"
            mine = sorted((number(r["stiffness"]), r) for r in rows
                          if r["integrator"] == method and number(r["mass"]) == mass)
            said = oscillator_series(ratio_ax, map_ax, key, mine, ctx.styles.line(key))
            if said:
                untheorised.append(said)
        ratio_ax.axhline(1.0, color="black", lw=1)
        ratio_ax.set_xlabel("spring stiffness k [N/m]")
        ratio_ax.set_ylabel("largest stable step measured / theory [1]")
        ratio_ax.set_title(f"measured over theory (m = {mass:g} kg)", fontsize=10)
        ratio_ax.grid(True, which="both", alpha=0.3)
        map_ax.set_xlabel("spring stiffness k [N/m]")
        map_ax.set_ylabel("largest stable step [s]")
        map_ax.set_title("the map (thin dashed: theory; hollow: stable at the largest step tried)", fontsize=9)
        map_ax.grid(True, which="both", alpha=0.3)
        handles, labels = map_ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="upper left", bbox_to_anchor=(0.81, 0.88), fontsize=7.5, frameon=False)
        return ["Without a theory: " + "; ".join(untheorised) + "."] if untheorised else []
    return Page("stability_oscillator", oscillator_title(rows),
                "Left: the largest step each integrator survives on a single damped oscillator, divided by the "
                "theory for its scheme (1 = exactly as predicted; above 1, the damping helps). The problem is "
                "scale-free, so the ratio is the finding and the map on the right is only parallel lines: "
                "h_max = c / w with c = 2 for symplectic Euler and Verlet, 2.83 for RK4.", draw)


# mysim's "trapezoidal" is Heun's explicit method (not the implicit trapezoidal rule): said wherever
# the name is shown on this page.
def integrator_label(name):
    return "trapezoidal (Heun, explicit)" if name == "trapezoidal" else name


def extremes_title(rows):
    """The answer from the table: which schemes keep a million steps' energy, which lose or gain it."""
    ends = {r["integrator"]: number(r["value"]) for r in rows if r["quantity"] == "energy drift end"}
    if not ends:
        return "What happens far from the usual runs?"
    kept = [n for n, d in ends.items() if abs(d) < 0.1]
    lost = [n for n, d in ends.items() if d <= -0.5]
    gained = [n for n, d in ends.items() if d >= 0.5]
    worst_kept = max((abs(ends[n]) for n in kept), default=0.0)
    parts = []
    if kept:
        parts.append(f"{len(kept)} schemes keep the energy within {100 * worst_kept:.1f} %")
    if lost:
        parts.append(f"{', '.join(lost)} lose{'s' if len(lost) == 1 else ''} it")
    for n in gained:
        parts.append(f"{'Heun' if n == 'trapezoidal' else n} gains {100 * ends[n]:.0f} %")
    return "1e6 steps: " + "; ".join(parts)


def extremes_page(path):
    rows = read_csv(path)

    def draw(fig, ctx):
        ax = fig.add_axes((0.06, 0.2, 0.88, 0.68))
        ax.axis("off")
        cells = [[r["case"], integrator_label(r["integrator"]), r["quantity"], f"{number(r['value']):.4g}",
                  r["unit"]] for r in rows]
        table = ax.table(cellText=cells, colLabels=["case", "integrator", "quantity", "value", "unit"],
                         colWidths=[0.3, 0.2, 0.3, 0.12, 0.08], loc="upper center", cellLoc="left")
        table.auto_set_font_size(False)
        table.set_fontsize(8)
        for (r, _), cell in table.get_celld().items():
            cell.set_height(min(1.0 / (len(cells) + 1), 0.05))
            cell.set_edgecolor("0.85")
            if r == 0:
                cell.set_text_props(weight="bold")
                cell.set_facecolor("#eeeeee")
        return []
    return Page("stability_extremes", extremes_title(rows),
                "springcheck stability --extremes: a million steps of the oscillator at h w = 0.1 (energy drift "
                "relative to the start: its largest excursion and its value at the end, signed; wall time, of "
                "runs made side by side on the machine's cores (--jobs), so a comparison of two rows' times is "
                "of a shared machine, not of the schemes alone), and "
                "one step of a 256 x 256 cloth. Bounded drift over a million steps is the symplectic signature. "
                "An end drift of -1 means the energy is gone (a dissipative scheme: backward Euler); +1 means "
                "it doubled (a scheme that pumps energy in: Heun's explicit method, which mysim calls "
                "trapezoidal).", draw)


def engine_label(engine, iterations):
    """The engine's row name, wrapped at its ':' parameters so a long setup stays beside its row,
    not over the next panel."""
    return wrap_setup(engine + (f" ({iterations} passes)" if iterations else ""))


def engine_summary(rows):
    """engine label -> ('theory', min, max ratio) | ('limit', min, max h w_max) | ('stable',) |
    ('refused',) | ('never',): what its cells say over every stiffness scale and mass ratio."""
    summary = {}
    for key in sorted({(r["engine"], r["classic_iterations"]) for r in rows}):
        mine = [r for r in rows if (r["engine"], r["classic_iterations"]) == key]
        ratios = [number(r["ratio"]) for r in mine if r["status"] == "bracketed" and number(r["ratio"])]
        hw = [number(r["h_w_max"]) for r in mine if r["status"] == "bracketed" and number(r["h_w_max"])]
        label = engine_label(*key).replace("\n", "")
        if ratios:
            summary[label] = ("theory", min(ratios), max(ratios))
        elif hw:
            summary[label] = ("limit", min(hw), max(hw))
        elif any(r["status"] == "stable-at-max" for r in mine):
            summary[label] = ("stable",)
        else:
            refused = any(r["status"] == "refused" for r in mine)
            summary[label] = ("refused",) if refused else ("never",)
    return summary


def plain(x):
    """A number as a reader says it: 0.026, 18, 1130 (no exponent)."""
    return f"{x:.2g}" if x < 100 else f"{x:.0f}"


def names(labels, most=2):
    """A few names in full, else their count."""
    return ", ".join(labels) if len(labels) <= most else f"{len(labels)} engines"


def scene_title(scene, rows):
    """The answer from the table: how close the schemes with a theory come to it (worst and best
    cell), which engines have a limit without one, which were stable at every step tried."""
    summary = engine_summary(rows)
    theory = [s for s in summary.values() if s[0] == "theory"]
    limited = [label for label, s in summary.items() if s[0] == "limit"]
    stable = [label for label, s in summary.items() if s[0] == "stable"]
    parts = []
    if theory:
        parts.append(f"{len(theory)} schemes at x{min(s[1] for s in theory):.2f} to "
                     f"x{max(s[2] for s in theory):.2f} of their theory")
    if limited:
        low, high = min(summary[n][1] for n in limited), max(summary[n][2] for n in limited)
        parts.append(f"{names(limited, 1)} limited at h\u00a0w_max {plain(low)} to {plain(high)} (no theory)")
    if stable:
        parts.append(f"{names(stable)} stable at every step tried")
    return f"{scene}: " + ("; ".join(parts) if parts else "no engine has a stable step")


def draw_map_series(map_ax, base, label, kw):
    """One engine on the map at the lowest mass ratio: a line through the limits found, hollow
    markers where it was still stable at the largest step tried (its limit lies above: never drawn
    as if it were one), its theory thin and dashed."""
    found = [(k, number(r["h_stable"])) for k, r in base if r["status"] == "bracketed" and number(r["h_stable"])]
    capped = [(k, number(r["h_stable"])) for k, r in base if r["status"] == "stable-at-max" and number(r["h_stable"])]
    if found:
        map_ax.loglog(*zip(*found), label=label, **kw)
    if capped:
        map_ax.loglog(*zip(*capped), linestyle="none", marker=kw["marker"], markerfacecolor="none",
                      markeredgecolor=kw["color"], markersize=7, label=None if found else label + " (stable)")
    theory = [(k, number(r["theory_h"])) for k, r in base if number(r["theory_h"])]
    if theory:
        map_ax.loglog(*zip(*theory), color=kw["color"], lw=0.8, linestyle=(0, (4, 3)))


def draw_limit_row(limit_ax, mine, ratios, row_index, kw):
    """One engine's row of h w_max: a filled dot per limit found, a hollow one per cell still
    stable at the largest step tried (drawn there), the mass ratios stacked top to bottom."""
    for j, ratio in enumerate(ratios):
        at_ratio = [r for r in mine if number(r["mass_ratio"]) == ratio]
        y = row_index + (j - (len(ratios) - 1) / 2) * 0.22
        hw = [number(r["h_w_max"]) for r in at_ratio if r["status"] == "bracketed" and number(r["h_w_max"])]
        limit_ax.scatter(hw, [y] * len(hw), color=kw["color"], marker=kw["marker"], s=22, alpha=0.85,
                         edgecolors="none")
        capped = [number(r["h_stable"]) * number(r["w_max"]) for r in at_ratio
                  if r["status"] == "stable-at-max" and number(r["h_stable"]) and number(r["w_max"])]
        limit_ax.scatter(capped, [y] * len(capped), facecolors="none", edgecolors=kw["color"],
                         marker=kw["marker"], s=26, linewidths=1.2)
    if not any(r["status"] == "bracketed" and number(r["h_w_max"]) for r in mine):
        found = [r for r in mine if r["status"] in FOUND]
        text = ("stable at every step tried" if found else
                "refuses this model" if any(r["status"] == "refused" for r in mine) else "never stable")
        limit_ax.annotate(text, (0.02, row_index), xycoords=("axes fraction", "data"), va="center",
                          fontsize=7.5, color=kw["color"])
    measured = [number(r["ratio"]) for r in mine if number(r["ratio"]) and r["status"] == "bracketed"]
    c = [number(r["theory_h"]) * number(r["w_max"]) for r in mine if number(r["theory_h"])]
    if c:
        limit_ax.plot([c[0], c[0]], [row_index - 0.42, row_index + 0.42], color="black", lw=1.6)
    if measured:
        limit_ax.annotate(f"x{min(measured):.2f}..{max(measured):.2f}", (1.0, row_index),
                          xycoords=("axes fraction", "data"), xytext=(4, 0),
                          textcoords="offset points", va="center", fontsize=7)


def label_axes(map_ax, limit_ax, labels, ratio):
    limit_ax.set_xscale("log")
    limit_ax.set_yticks(range(len(labels)), labels, fontsize=7.5 if len(labels) < 14 else 6.5)
    limit_ax.invert_yaxis()
    limit_ax.set_xlabel("largest stable step times the highest natural frequency, h w_max [1]")
    limit_ax.set_title("the limit at every cell, scale-free; black bar: theory c; right: measured / theory",
                       fontsize=9)
    limit_ax.grid(True, axis="x", which="both", alpha=0.3)
    map_ax.set_xlabel("spring stiffness, times the scene's own (1 = as written) [1]")
    map_ax.set_ylabel("largest stable step [s]")
    map_ax.set_title(f"the map at neighbour mass ratio {ratio:g} only (thin dashed: theory c / w_max)", fontsize=9)
    map_ax.grid(True, which="both", alpha=0.3)
    # No legend over the lines: each engine keeps its colour and marker in its row on the right.


def scene_page(entry):
    scene = entry["scene"]
    rows = read_csv(entry["path"])

    def draw(fig, ctx):
        ratios = sorted({number(r["mass_ratio"]) for r in rows})
        engines = sorted({(r["engine"], r["classic_iterations"]) for r in rows})
        labels = [engine_label(*e) for e in engines]
        gap = 0.32 + 0.016 * max(0, max(len(line) for t in labels for line in t.split("\n")) - 24)
        grid = plot_area(fig, 1, 2, right=0.92, wspace=gap, width_ratios=(1, 1.15))
        map_ax, limit_ax = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1])
        notes = []
        for row_index, (engine, iterations) in enumerate(engines):
            variant = sorted({e[1] for e in engines if e[0] == engine}).index(iterations)
            kw = ctx.styles.line(engine, variant)
            mine = [r for r in rows if (r["engine"], r["classic_iterations"]) == (engine, iterations)]
            base = sorted((number(r["stiffness_scale"]), r) for r in mine if number(r["mass_ratio"]) == ratios[0])
            draw_map_series(map_ax, base, labels[row_index], kw)
            refused = sorted({number(r["mass_ratio"]) for r in mine if r["status"] == "refused"})
            if refused:
                notes.append((engine, ", ".join(f"{v:g}" for v in refused)))
            draw_limit_row(limit_ax, mine, ratios, row_index, kw)
        label_axes(map_ax, limit_ax, labels, ratios[0])
        spread = ", ".join(f"{r:g}" for r in ratios)
        return [f"Left: a line joins the limits found (each engine in the colour and marker of its row on the "
                f"right); a hollow marker is a step still stable, the largest tried (the limit lies above it). Right: one row per engine, one dot per stiffness scale, the dots of "
                f"mass ratios {spread} stacked top to bottom; filled: the limit found, hollow: stable at the largest "
                f"step tried. The title's ratios span every cell, all mass ratios included."] + \
            [f"{engine} refuses mass ratio {ratios_text} (no dots there)." for engine, ratios_text in sorted(set(notes))]
    return Page(f"stability_{scene}", scene_title(scene, rows),
                "Every engine's largest stable step, found by bisection, on the scene as written with all its "
                "springs' stiffness scaled by one factor, across that factor and the neighbour "
                "mass ratio (stiffer springs and lighter masses raise the highest natural frequency w_max, found "
                "by Lanczos). Left: the step itself. Right: h w_max, which removes the scale: an engine whose "
                "dots sit on its black bar is exactly as stable as its scheme's theory. Each trial runs a fixed "
                "number of steps from the scene's seeded start (springcheck stability --steps, 4000 unless the "
                "command above says otherwise), so a limit holds for that many steps, not for the scene's own "
                "duration.", draw)


def pages(manifest):
    stability = manifest["stability"]
    result = [oscillator_page(stability["stability"])] if stability.get("stability") else []
    if stability.get("extremes"):
        result.append(extremes_page(stability["extremes"]))
    return result + [scene_page(s) for s in stability["scenes"]]
