"""Energy: how far each engine's total energy wanders from what the physics allows."""
from collections import defaultdict

from report_style import Page, coincident, draw_coincidences, number, plot_area, read_csv

# The series tables carry 10 significant digits: relative differences below ~1e-10 are rounding.
FLOOR = 1e-11


def label(engine):
    plain = engine["name"] == "mysim" and engine["integrator"]
    return engine["name"] + (f" ({engine['integrator']})" if plain else "")


def drift_column(c, damped):
    """Damped scenes: each engine against the comparison's energy reference (the run of the
    highest-order fixed-step integrator), as springcheck computed it; else the balance itself.
    Returns (column, the reference engine or None)."""
    reference = None
    if damped and c.get("energy_reference"):
        reference = next((e for e in c["engines"] if e["name"] == c["energy_reference"]), None)
    return ("energy_drift_vs_reference" if reference is not None else "energy_drift_total"), reference


def read_drift(c, column):
    drift = defaultdict(dict)  # engine -> t -> the drawn value
    for r in read_csv(c["series"]):
        value = number(r.get(column))
        if value is not None:
            drift[r["engine"]][r["t"]] = abs(value)
    return drift


def energy_title(c, damped):
    """The answer: how many engines keep the drawn drift within 1 % of E_ref, and the worst."""
    column, _ = drift_column(c, damped)
    drift = read_drift(c, column)
    worst = {e["name"]: max(drift[e["name"]].values()) for e in c["engines"] if drift.get(e["name"])}
    if not worst:
        return f"Does each engine keep the energy it should? ({c['scene']})"
    kept = [n for n, w in worst.items() if w <= 0.01 and
            next(e for e in c["engines"] if e["name"] == n)["status"] == "ok"]
    name = max(worst, key=worst.get)
    beyond = " beyond the physical loss" if damped else ""
    return (f"{c['scene']} ({'damped' if damped else 'undamped'}): {len(kept)} of {len(worst)} engines keep the "
            f"energy within 1 % of E_ref{beyond}; worst {name} ({worst[name]:.2g})")


def comparison_page(c):
    model = c.get("model", {})
    damped = bool(model.get("damped"))
    driven = bool(model.get("driven"))

    def draw(fig, ctx):
        ax = fig.add_subplot(plot_area(fig, right=0.8)[0, 0])
        column, reference = drift_column(c, damped)
        drift = read_drift(c, column)
        engines = [e for e in c["engines"] if e["name"] in drift]
        notes, drawn = [], {}
        for e in engines:
            pts = [(number(t), v) for t, v in drift[e["name"]].items()]
            pts = sorted((t, max(v, FLOOR)) for t, v in pts)
            kw = ctx.styles.line(ctx.styles.key_of(e))
            kw["marker"] = None
            drawn[label(e)] = (pts, kw)
            ax.semilogy(*zip(*pts), label=label(e) + ("" if e["status"] == "ok" else f" [{e['status']}]"), **kw)
            if e["status"] != "ok":
                notes.append(f"{label(e)} stopped early ({e['status']}): its line ends there.")
        notes += draw_coincidences(ax, coincident({k: v[0] for k, v in drawn.items()}),
                                   lambda k: ([p[0] for p in drawn[k][0]], [p[1] for p in drawn[k][0]], drawn[k][1]),
                                   markers=False)
        ax.set_xlabel("time t [s]")
        if reference is not None:
            ax.set_ylabel(f"|energy balance - {label(reference)}'s| / E_ref [1]")
        else:
            ax.set_ylabel("|E(t) - E(0) - W(t)| / E_ref [1]")
        ax.set_ylim(bottom=FLOOR)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
        return notes

    scene = c["scene"]
    if damped:
        caption = ("A damped scene loses energy by physics, the same in every correct engine, so the plain "
                   "energy curves lie on top of each other. Drawn instead: each engine's energy balance "
                   "(E(t) - E(0) - W(t)) / E_ref minus that of mysim's RK4, the most accurate fixed-step run, on "
                   "a log scale: how much energy each scheme adds or removes beyond the physical loss. The floor, "
                   "1e-11, is the tables' rounding.")
    else:
        caption = ("Energy balance |E(t) - E(0) - W(t)| / E_ref on a log scale (W: work done from outside"
                   + (", here by the scene's drivers" if driven else ", none here") + "; E_ref: the scene's "
                   "energy scale). A flat band is bounded oscillation (symplectic methods); a line that keeps "
                   "rising is drift; a line that ends has blown up.")
    return Page(f"energy_{c['group'].replace('/', '_')}_{scene}",
                energy_title(c, damped),
                caption, draw)


def pages(manifest):
    chosen = [c for c in manifest["comparisons"] if c["group"] in ("energy", "compare") and c.get("series")
              and c.get("model", {}).get("kind") != "circle"]
    return [comparison_page(c) for c in chosen]
