"""Page 2: the engines ranked scene by scene, one panel per quantity (each with its own colour
bar and unit: errors against closed forms in metres and relative, rest-shape and trajectory
distances to the scene's first engine), and the largest disagreements between engines. Every
number comes from `springcheck report` (manifest headlines "ranking", "worst_cloth_drape",
"worst_moving_cloth", "momentum"); this only words and draws."""
import math
import textwrap

import numpy as np
from matplotlib import colors
from matplotlib.patches import Rectangle

from report_style import Page

# The panels, in reading order (row, then column), each one quantity with its unit.
PANELS = [("closed form", "m", "error against the closed form [m]"),
          ("closed form", "rel", "relative error against the closed form [1]"),
          ("trajectory", "m", "trajectory: largest RMS distance to {ref} over the run [m]"),
          ("rest shape", "m", "rest shape: largest node distance to {ref} (mirror-aware) [m]")]


def panel_of(scene):
    measure = scene["measure"]
    kind = "closed form" if measure == "closed form" else measure.split(" vs ")[0]
    return kind, scene.get("unit", "m")


def grid(scenes, engines):
    values = np.full((len(engines), len(scenes)), np.nan)
    for j, s in enumerate(scenes):
        for i, e in enumerate(engines):
            if e in s["values"] and s["values"][e] > 0:
                values[i, j] = s["values"][e]
    return values


def draw_panel(fig, rect, scenes, engines, label, show_engines):
    """One quantity: engines down, scenes across, darker is closer; its own log colour bar."""
    ax = fig.add_axes(rect)
    values = grid(scenes, engines)
    finite = values[np.isfinite(values)]
    low = max(finite.min(), 1e-16) if finite.size else 1e-16
    norm = colors.LogNorm(vmin=low, vmax=max(finite.max(), low * 10) if finite.size else 1.0)
    image = ax.imshow(np.ma.masked_invalid(values), cmap="viridis", norm=norm, aspect="auto")
    for i, e in enumerate(engines):
        for j, s in enumerate(scenes):
            if math.isfinite(values[i, j]):
                ax.text(j, i, f"{values[i, j]:.0e}".replace("e-0", "e-"), ha="center", va="center", fontsize=6,
                        color="white" if norm(values[i, j]) < 0.55 else "black")
            elif s["values"].get(e) == 0.0:  # the reference engine itself, or exactly equal to it
                ax.text(j, i, "ref" if s["measure"] != "closed form" else "0", ha="center", va="center",
                        fontsize=6, color="0.3")
            if e in s["not_ok"]:
                ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False, edgecolor="red", lw=1.5))
    marks = {"settled": "", "moving": " (moving)", "driven": " (driven)"}
    ax.set_xticks(range(len(scenes)), [s["scene"] + marks.get(s["state"]["state"], "") for s in scenes],
                  rotation=40, ha="right", rotation_mode="anchor", fontsize=6.5)
    ax.set_yticks(range(len(engines)), engines if show_engines else [""] * len(engines), fontsize=7)
    ax.set_title(label, fontsize=8)
    bar = fig.colorbar(image, ax=ax, pad=0.01, fraction=0.06 if len(scenes) > 4 else 0.2)
    bar.ax.tick_params(labelsize=6)


def panel_rects(counts, bottom, height):
    """Axes rectangles for one row of panels, widths by their number of scenes."""
    left, width = 0.1, 0.86
    shares = [n + 2 for n in counts]  # each panel also holds its colour bar
    rects, x = [], left
    for share in shares:
        w = width * share / sum(shares)
        rects.append((x, bottom, w - 0.035, height))
        x += w
    return rects


def headline_lines(h):
    lines = []
    worst = h.get("worst_cloth_drape")
    if worst:
        how = "to the other's mirror image" if worst.get("mirrored") else "direct, mirror-aware"
        lines.append(f"Largest disagreement between settled cloths: {worst['value'] * 1e3:.3g} mm (max node distance, "
                     f"{how}) between {worst['a']} and {worst['b']} on {worst['scene']}, settled by t = "
                     f"{worst['state']['settled_at']:.3g} s.")
    moving = h.get("worst_moving_cloth")
    if moving:
        lines.append(f"Cloths not at rest, by trajectory: the largest RMS difference over the run's "
                     f"{moving['state']['last_frame']:.3g} s is {moving['value'] * 1e3:.3g} mm, between {moving['a']} "
                     f"and {moving['b']} on {moving['scene']} ({moving['state']['state']}).")
    return lines


def draw(fig, ctx):
    h = ctx.manifest.get("headlines", {})
    scenes, engines = h.get("ranking", []), [v["engine"] for v in h.get("verdicts", [])]
    if not scenes or not engines:
        return ["No suite comparison in the results: nothing to rank."]
    fig.text(0.06, 0.895, "\n".join(textwrap.wrap(" ".join(headline_lines(h)), 190)), fontsize=7.5, va="top")
    rows = [[], []]  # closed forms on the first row, distances to a reference on the second
    for kind, unit, label in PANELS:
        members = [s for s in scenes if panel_of(s) == (kind, unit)]
        if members:
            ref = members[0]["measure"].split(" vs ")[-1]
            rows[kind != "closed form"].append((members, label.format(ref=ref)))
    for row, bottom in zip(rows, (0.66, 0.33)):
        rects = panel_rects([len(m) for m, _ in row], bottom, 0.15)
        for c, ((members, label), rect) in enumerate(zip(row, rects)):
            draw_panel(fig, rect, members, engines, label, c == 0)
    return []


def title(ctx):
    scenes = ctx.manifest.get("headlines", {}).get("ranking", [])
    failed = sum(len(s["not_ok"]) for s in scenes)
    return f"How do the engines rank scene by scene? {len(scenes)} scenes; {failed} runs did not finish (red)"


def page(ctx):
    return Page("verdicts", title(ctx),
                "One panel per quantity, each with its own colour bar: a scene with a closed form ranks the engines "
                "by their error against it (in metres, or relative where the closed form is a period or a "
                "frequency); one without ranks them by their distance to its first engine (ref): the rest shape "
                "where every engine settled, the trajectory where the cloth is still moving or driven at its last "
                "frame (so a chaotic scene, chain_swing, ranks engines by how soon round-off grows, not by "
                "accuracy). Darker is closer. A blank cell: the engine refuses the scene. A red frame: the run "
                "blew up or stopped at a solver limit there.", draw)
