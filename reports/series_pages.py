"""Sag and collider penetration over time, one panel per scene, every engine in each."""
import math
from collections import defaultdict

from report_style import Page, coincidence_note, coincident, coincident_groups, number, plot_area, read_csv

PER_PAGE = 9


def read_series(c, column, scale):
    """engine -> [(t, value)] of one comparison's series table."""
    series = defaultdict(list)
    for r in read_csv(c["series"]):
        value = number(r[column])
        if value is not None:
            series[r["engine"]].append((number(r["t"]), scale * value))
    return series


def mark_state(ax, state):
    """When the scene settles (a dotted line at the time every engine's motion died down), or
    that it never does within the run (still moving, or driven)."""
    if not state:
        return
    if state["state"] == "settled":
        ax.axvline(state["settled_at"], color="0.3", ls=":", lw=1)
        text = f"settled by t = {state['settled_at']:.2g} s"
    else:
        text = "driven: never at rest" if state["state"] == "driven" else "still moving at the end"
    ax.text(0.98, 0.04, text, transform=ax.transAxes, ha="right", va="bottom", fontsize=6.5, color="0.3")


def panels_page(key, title, caption, chosen, column, scale, ylabel, states=None):
    def draw(fig, ctx):
        cols = min(3, len(chosen))
        rows = math.ceil(len(chosen) / cols)
        grid = plot_area(fig, rows, cols, top=0.85, wspace=0.25, hspace=0.45)
        handles, notes = {}, []
        for i, c in enumerate(chosen):
            ax = fig.add_subplot(grid[i // cols, i % cols])
            series = read_series(c, column, scale)
            integrators = {e["name"]: e["integrator"] for e in c["engines"]}
            series = {ctx.styles.key(n, integrators.get(n, "")): pts for n, pts in series.items()}
            for group in coincident_groups(coincident(series)):
                notes.append(f"On {c['scene']}: " + coincidence_note(group))
            for label, pts in series.items():  # plain "mysim" is named by its integrator
                kw = ctx.styles.line(ctx.styles.key(label))
                kw["marker"] = None
                line, = ax.plot(*zip(*pts), label=label, **kw)
                handles.setdefault(label, line)
            ax.set_title(c["scene"], fontsize=9)
            if states is not None:
                mark_state(ax, states.get(c["scene"]))
            elif series and all(v == 0 for pts in series.values() for _, v in pts):
                ax.text(0.5, 0.75, "no node inside, in any engine", transform=ax.transAxes, ha="center",
                        fontsize=8, color="0.3")
            ax.tick_params(labelsize=7)
            ax.grid(True, alpha=0.3)
            if i % cols == 0:
                ax.set_ylabel(ylabel, fontsize=8)
            if i // cols == rows - 1:
                ax.set_xlabel("time t [s]", fontsize=8)
        fig.legend(list(handles.values()), list(handles), fontsize=7.5, ncol=min(6, len(handles)),
                   loc="upper center", bbox_to_anchor=(0.5, 0.925), frameon=False)
        return notes
    return Page(key, title, caption, draw)


def chunks(items):
    return [items[i:i + PER_PAGE] for i in range(0, len(items), PER_PAGE)]


def deepest(chosen, column, scale):
    """The deepest value any engine reaches on these scenes: (value, engine, scene)."""
    worst = (0.0, "", "")
    for c in chosen:
        for engine, pts in read_series(c, column, scale).items():
            for _, v in pts:
                worst = max(worst, (v, engine, c["scene"]))
    return worst


def sag_title(part, states):
    settled = sum(1 for c in part if (states.get(c["scene"]) or {}).get("state") == "settled")
    return (f"How far does each engine let the system sag? {settled} of {len(part)} scenes settle "
            "(dotted line: when)")


def penetration_title(part):
    value, engine, scene = deepest(part, "penetration_deepest", 1e3)
    if value <= 0:
        return "Does any engine let the cloth sink into a collider? No: no node inside, in any engine"
    return f"Does any engine let the cloth sink into a collider? Deepest {value:.2g} mm: {engine} on {scene}"


def pages(manifest):
    result = []
    # Each suite scene's state at its last frame (springcheck report: settled by when, moving, driven).
    states = {s["scene"]: s["state"] for s in manifest.get("headlines", {}).get("ranking", [])}
    with_sag = [c for c in manifest["comparisons"] if c["group"] not in ("energy",) and c.get("series")
                and c.get("model", {}).get("kind") in ("chain", "cloth")]
    for n, part in enumerate(chunks(with_sag)):
        part_states = {c["scene"]: states.get(c["scene"]) for c in part if c["group"] == "suite"}
        result.append(panels_page(
            f"sag_{n + 1}", sag_title(part, part_states),
            "Depth of the lowest node below the pins (along gravity; with driven pins, below where they are "
            "at that time; without pins, below the highest particle at the start), per scene and engine, over "
            "the run. Dotted line: every engine's kinetic energy stayed below 1e-4 of its peak from then on. "
            "Lines that end early belong to runs that blew up; lines that part show engines that settle to "
            "different shapes (the drape pages show where).", part, "sag_lowest", 1.0,
            "lowest point below the pins [m]", part_states))
    with_colliders = [c for c in manifest["comparisons"] if c["group"] not in ("energy",) and c.get("series")
                      and c.get("model", {}).get("colliders")]
    for n, part in enumerate(chunks(with_colliders)):
        result.append(panels_page(
            f"penetration_{n + 1}", penetration_title(part),
            "Depth of the deepest node inside a collider (sphere, ground plane or box; 0: none inside), per scene "
            "and engine, over the run, in millimetres. mysim projects every node out after each step; Bullet "
            "corrects contacts through a signed-distance field, so a node may sit inside between corrections.",
            part, "penetration_deepest", 1e3, "deepest node inside [mm]"))
    return result
