"""Sag and collider penetration over time, one panel per scene, every engine in each."""
import math
from collections import defaultdict

from report_style import Page, coincidence_note, coincident, coincident_groups, number, plot_area, read_csv

PER_PAGE = 9


def panels_page(key, title, caption, chosen, column, scale, ylabel):
    def draw(fig, ctx):
        cols = min(3, len(chosen))
        rows = math.ceil(len(chosen) / cols)
        grid = plot_area(fig, rows, cols, top=0.85, wspace=0.25, hspace=0.45)
        handles, notes = {}, []
        for i, c in enumerate(chosen):
            ax = fig.add_subplot(grid[i // cols, i % cols])
            series = defaultdict(list)
            for r in read_csv(c["series"]):
                value = number(r[column])
                if value is not None:
                    series[r["engine"]].append((number(r["t"]), scale * value))
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


def pages(manifest):
    result = []
    with_sag = [c for c in manifest["comparisons"] if c["group"] not in ("energy",) and c.get("series")
                and c.get("model", {}).get("kind") in ("chain", "cloth")]
    for n, part in enumerate(chunks(with_sag)):
        result.append(panels_page(
            f"sag_{n + 1}", "How far does each engine let the system sag, and when does it settle?",
            "Depth of the lowest node below the pins (along gravity; with driven pins, below where they are "
            "at that time; without pins, below the highest particle at the start), per scene and engine, over "
            "the run. Lines that end "
            "early belong to runs that blew up; lines that part show engines that settle to different "
            "shapes (the drape pages show where).", part, "sag_lowest", 1.0, "lowest point below the pins [m]"))
    with_colliders = [c for c in manifest["comparisons"] if c["group"] not in ("energy",) and c.get("series")
                      and c.get("model", {}).get("colliders")]
    for n, part in enumerate(chunks(with_colliders)):
        result.append(panels_page(
            f"penetration_{n + 1}", "Does any engine let the cloth sink into a collider?",
            "Depth of the deepest node inside a collider (sphere, ground plane or box; 0: none inside), per scene and engine, over the "
            "run, in millimetres. mysim projects every node out after each step; Bullet corrects contacts "
            "through a signed-distance field, so a node may sit inside between corrections.",
            part, "penetration_deepest", 1e3, "deepest node inside [mm]"))
    return result
