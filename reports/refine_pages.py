"""Convergence as the mesh is refined (springcheck refine): one page per scene, each shape quantity
against the resolution for every engine, its Richardson limit and, where the scene has one, the
closed form (the heavy elastica's tip drop)."""
from report_style import Page, coincident, number, plot_area, read_csv

LABELS = {  # how a quantity reads on an axis (units from the estimates table)
    "sag_lowest": "lowest point below the pins",
    "tip_drop": "tip drop below the clamp",
    "chord_angle": "chord angle below level",
    "bending_length": "bending length read from the chord",
    "drape_coefficient": "drape coefficient",
    "drape_folds": "folds",
}


REFERENCES = {"tip_drop": "heavy elastica", "sag_lowest": "continuous elastic catenary"}


def page(scene, rows, estimates, command):
    quantities = [q for q in LABELS if any(number(r[q]) is not None for r in rows)]
    if "tip_drop" in quantities:  # a strip's lowest point is its tip: one panel, not two
        quantities.remove("sag_lowest")
    bending = rows[0]["bending"]
    bent = f" ({bending} bending)" if not bending.startswith("none") else ""

    def draw(fig, ctx):
        grid = plot_area(fig, rows=2, cols=2, hspace=0.55, wspace=0.28, top=0.84, left=0.08)
        notes, drawn = [], {}
        engines = sorted({r["engine"] for r in rows})
        for k, quantity in enumerate(quantities[:4]):
            ax = fig.add_subplot(grid[k // 2, k % 2])
            unit, orders = "", []
            for engine in engines:
                series = [(int(r["resolution"]), number(r[quantity])) for r in rows
                          if r["engine"] == engine and r["status"] == "ok" and number(r[quantity]) is not None]
                if not series:
                    continue
                drawn.setdefault(quantity, {})[engine] = series
                style = ctx.styles.line(ctx.styles.key(engine))
                ax.plot([n for n, _ in series], [v for _, v in series], label=engine, **style)
                est = next((e for e in estimates if e["engine"] == engine and e["quantity"] == quantity), None)
                if not est:
                    continue
                unit = est["unit"]
                # The table holds a limit and an order only where the evidence rule allows them
                # (refine_estimates.csv's verdict); the page draws nothing more than the table says.
                if est["extrapolated_limit"]:
                    ax.axhline(float(est["extrapolated_limit"]), color=style["color"], linestyle=":", linewidth=1)
                    ctx.claims.append({"page": f"refine_{scene}", "kind": "limit", "engine": engine,
                                       "quantity": quantity, "resolutions": est.get("resolutions", ""),
                                       "observed_order": est["observed_order"],
                                       "expected_order": est.get("expected_order", ""),
                                       "verdict": est.get("verdict", "")})
                counted = (est.get("verdict") or "").startswith("a count")
                orders.append(f"{engine}: " + (f"order {float(est['observed_order']):.2f}" if est["observed_order"]
                                                else "a count (no order)" if counted else "not converged"))
                if est["reference"] and not any(n.startswith("closed form") for n in notes):
                    ax.axhline(float(est["reference"]), color="black", linewidth=1.2,
                               label=REFERENCES.get(quantity, "closed form"))
                if est["reference"]:
                    notes.append(f"closed form: {engine} at {est['finest_resolution']} cells is "
                                 f"{100 * float(est['finest_vs_reference_rel']):+.3f} % off")
            ax.set_xscale("log", base=2)
            ax.set_xlabel("resolution (cells across; a chain's links)")
            ax.set_ylabel(f"[{unit}]" if unit and unit != "1" else "")
            ax.set_title(LABELS[quantity] + "\n" + "; ".join(orders), fontsize=9)
            ax.grid(True, alpha=0.3)
            if k == 0:
                ax.legend(fontsize=7, loc="center right")
        hidden = {}
        for quantity, series in drawn.items():
            for pair in coincident(series):
                hidden.setdefault(pair, []).append(LABELS[quantity])
        for (a, b), where in hidden.items():
            notes.append(f"{b} lies under {a} within 1 % ({', '.join(where)})")
        for engine in engines:
            failed = [r for r in rows if r["engine"] == engine and r["status"] != "ok"]
            if failed:
                notes.append(f"{engine} did not complete at " + ", ".join(r["resolution"] for r in failed)
                             + " cells (" + ", ".join(sorted({r["status"] for r in failed}))
                             + "; refine's output says when)")
        prefix = "no closed form: "
        why_not = sorted({r["note"][len(prefix):] for r in rows if (r.get("note") or "").startswith(prefix)})
        if why_not and not any(r.get("closed_form_value") for r in rows):
            notes.append("no black line, as " + "; ".join(why_not))
        return ["; ".join(dict.fromkeys(notes)) + "."] if notes else []

    verdicts = [e for e in estimates if e["quantity"] in quantities]
    converged = [e for e in verdicts if (e.get("verdict") or "").startswith("converged")]
    expected = sorted({e["expected_order"] for e in verdicts if e.get("expected_order")})
    if verdicts and len(converged) == len(verdicts):
        title = f"{scene} converges as its mesh is refined" + (f" (expected order {', '.join(expected)})" if expected else "")
    elif not converged:
        title = f"{scene}: not converged at {', '.join(dict.fromkeys(r['resolution'] for r in rows))} cells"
    else:
        title = f"{scene}: {len(converged)} of {len(verdicts)} series converged at these resolutions"
    why_not = sorted({e["verdict"].split(": ", 1)[-1] for e in verdicts if e not in converged and e.get("verdict")})
    caption = (f"{scene}{bent} at each resolution. Dotted: the Richardson limit, drawn only with the evidence "
               "for one (four or more resolutions whose last two triples give agreeing orders, or three at the "
               "discretisation's expected order" + (f", {' and '.join(expected)} here" if expected else ": none here")
               + ", within 30 %); black: the closed form. Above each panel: each engine's observed order, or "
               "'not converged'" + (" (" + "; ".join(why_not[:3]) + ")" if why_not else "") + ".")
    return Page(f"refine_{scene}", title, caption, draw, command=command)


def pages(m):
    refine = m.get("refine")
    if not refine:
        return []
    rows, estimates = read_csv(refine["table"]), read_csv(refine["estimates"])
    result = []
    for scene in dict.fromkeys(r["scene"] for r in rows):
        result.append(page(scene, [r for r in rows if r["scene"] == scene],
                           [e for e in estimates if e["scene"] == scene], refine.get("command") or None))
    return result
