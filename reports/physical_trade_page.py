"""The trade against physical truth (springcheck trade): per study, each setup's wall time against
its physical error, one marker per solver family, and the error budget of the recommended setup
and of each family's cheapest within the bound."""
import json
import math

from report_style import Page, plot_area, read_csv

PARTS = [("solver", "solver"), ("temporal", "temporal"), ("spatial", "spatial"),
         ("model", "model"), ("remainder", "remainder")]
MARKERS = "os^vD<>PXh*"


def short(setup, ms=False):
    """'16 cells, mysim vbd, dt 0.004 s' (the scene's resolution: cells, rings or links)."""
    integrator = "" if setup["integrator"] == "-" else " " + setup["integrator"]
    step = f"{1000 * setup['dt']:g} ms" if ms else f"dt {setup['dt']:g} s"
    return f"resolution {setup['resolution']}, {setup['engine']}{integrator}, {step}"


def title_of(a):
    bound = f"{100 * a['max_error']:g} %" if a["relative"] else f"{a['max_error']:g} {a['unit']}"
    head = f"{a['scene']}: {a['quantity']} within {bound}"
    r = a.get("recommended")
    if not a["reference"]["value"]:
        return f"{head}? No reference ({a['reference']['reason']})"
    if not r:
        c = a.get("closest")
        return f"{head}? No setup of the grid" + (f"; closest {short(c)}" if c else "")
    rel = abs(r["relative_error"]) * 100 if r["relative_error"] is not None else float("nan")
    return f"{head}: {short(r, ms=True)}, {rel:.2g} % in {r['wall_seconds']:.2g} s"


def draw_front(ax, a, rows):
    families = sorted({r["family"] for r in rows})
    for k, family in enumerate(families):
        pts = [(float(r["wall_seconds"]), abs(float(r["physical_error"]))) for r in rows
               if r["family"] == family and r["excluded"] == "" and r["physical_error"]]
        if pts:
            ax.loglog([p[0] for p in pts], [max(p[1], 1e-16) for p in pts], MARKERS[k % len(MARKERS)],
                      label=family, alpha=0.75, ms=5)
    ax.axhline(a["bound"], color="k", ls="--", lw=1, label=f"bound {a['bound']:.2g} {a['unit']}")
    for key, style in (("recommended", dict(marker="*", ms=16, mfc="none", mec="k")),
                       ("bullet_best", dict(marker="s", ms=12, mfc="none", mec="tab:red"))):
        s = a.get(key)
        if s:
            ax.loglog([s["wall_seconds"]], [max(abs(s["physical_error"]), 1e-16)], ls="none",
                      label=key.replace("_", "'s ").replace("bullet's best", "Bullet's best"), **style)
    r = a.get("recommended")
    if r:
        ax.annotate(short(r), (r["wall_seconds"], max(abs(r["physical_error"]), 1e-16)),
                    textcoords="offset points", xytext=(8, -14), fontsize=7)
    ax.set_xlabel("wall time of the run, s")
    ax.set_ylabel(f"|physical error|, {a['unit']}")
    ax.legend(fontsize=6.5, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # off the points


def draw_budgets(ax, a):
    chosen = []
    if a.get("recommended"):
        chosen.append((f"recommended\n{a['recommended']['family']}", a["recommended"]))
    for s in a.get("family_best", []):
        if not a.get("recommended") or short(s) != short(a["recommended"]):
            chosen.append((s["family"], s))
    low = high = 0.0
    for x, (label, s) in enumerate(chosen):
        up = down = 0.0
        for k, (part, name) in enumerate(PARTS):
            v = s["budget"].get(part) or 0.0
            base = up if v >= 0 else down
            ax.bar(x, v, bottom=base, color=f"C{k}", label=name if x == 0 else None)
            if v >= 0:
                up += v
            else:
                down += v
        ax.plot([x - 0.4, x + 0.4], [s["physical_error"]] * 2, "k-", lw=1.5)
        low, high = min(low, down, s["physical_error"]), max(high, up, s["physical_error"])
    ax.axhline(0, color="0.5", lw=0.5)
    pad = 0.1 * (high - low) or 1e-12
    ax.set_ylim(low - pad, high + pad)
    ax.set_xticks(range(len(chosen)), [c[0] for c in chosen], fontsize=6)
    ax.set_ylabel(f"signed error part, {a['unit']}")
    if chosen:
        ax.legend(fontsize=6.5, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)


def page(study):
    with open(study["answer"]) as f:
        a = json.load(f)
    rows = read_csv(study["table"])

    def draw(fig, ctx):
        grid = plot_area(fig, 1, 2, right=0.88, wspace=0.5)
        draw_front(fig.add_subplot(grid[0, 0]), a, rows)
        draw_budgets(fig.add_subplot(grid[0, 1]), a)
        notes = []
        if a["reference"].get("warning"):
            notes.append("the reference limit is not to be trusted: " + a["reference"]["warning"])
        notes.append(f"{a['blew_up']} setups blew up and {a['unsettled']} did not settle: never "
                     "recommended, not drawn")
        return ["; ".join(notes) + "."]

    ref = a["reference"]
    caption = (f"Left: every setup that settled, wall time against |value - reference| (reference "
               f"{ref['value']:.6g} {a['unit']}, {ref['source']}); dashed: the bound. Right: the error "
               "budget of the recommended setup and of each family's cheapest within the bound, "
               "signed parts stacked (solver: against the grid's most passes; temporal: against its "
               "smallest step; spatial: against the family's Richardson limit; model: that limit "
               "against the reference); the black line is the total." if ref["value"] is not None
               else "No physical reference: " + ref["reason"])
    return Page(f"trade_{a['scene']}_{a['quantity']}", title_of(a), caption, draw,
                command=study.get("command") or None)


def pages(m):
    return [page(s) for s in m.get("physical_trade") or []]
