"""Page 1: a verdict per engine (what to trust it for, where it is biased, its energy and momentum,
its largest stable step, the setups it wins), each number with the cut it was measured under; the
gate count beside the known biases its bounds allow; the largest disagreements. Every number is
found by `springcheck report` (manifest "headlines") or read from a study's table; this only
words and draws them."""
import json
import os
import textwrap

from report_style import Page

# Columns of the verdict table: heading, share of the table's width, characters per line at its
# 6.8-point type (about 3.7 points a character across 0.94 of an 842-point page).
COLUMNS = [("engine", 0.09, 18),
           ("trusted for: closed forms met to 1 % of the exact value (1 mm where it is 0)", 0.15, 30),
           ("biased where: the closed forms it misses, worst first (error, over the run's first T s)", 0.22, 46),
           ("energy and momentum: worst drift, scene and window", 0.17, 34),
           ("largest stable step: every cell mapped (all stiffness scales and mass ratios)", 0.19, 38),
           ("cheapest under 1 mm it wins (sweep scene, step)", 0.18, 36)]


def percent(x):
    return f"{100 * x:.2g} %" if x >= 0.01 else f"{100 * x:.1g} %"


def miss_text(m):
    """One closed form missed by a run that finished: its error as a fraction of the exact value
    where there is one, else in millimetres; with the run's window."""
    size = percent(m["relative"]) if "relative" in m else f"{m['value'] * 1e3:.3g} mm"
    return f"{m['scene']} {size} ({m['window']:.3g} s)"


def trust_cell(ctx, v):
    forms = v.get("closed_forms")
    text = f"{forms['trusted']} of {forms['scenes']} scenes" if forms else "no closed form run"
    if v.get("not_ok"):
        n = len(v["not_ok"])
        text += f"; {n} run{'s' if n > 1 else ''} did not finish at the scene's own step " \
                f"(red on {ctx.page_of('verdicts')})"
    return text


def bias_cell(ctx, v):
    misses = v.get("closed_forms", {}).get("misses", [])
    if not misses:
        return "none of its closed forms off by more than 1 %"
    measured = [m for m in misses if "status" not in m]
    ended = [m for m in misses if "status" in m]
    parts = [miss_text(m) for m in measured[:4]]
    if len(measured) > 4:
        parts.append(f"{len(measured) - 4} more [{ctx.page_of('closed_forms')}]")
    if ended:
        parts.append("did not finish: " + ", ".join(m["scene"] for m in ended))
    return "; ".join(parts)


def conservation_cell(v):
    parts = []
    if "energy_drift" in v:
        e = v["energy_drift"]
        parts.append(f"energy {e['value']:.2g} of E_ref ({e['scene']}, {e['window']:.3g} s)")
    momenta = [(word, v[key]) for key, word in (("linear_momentum", "linear"), ("angular_momentum", "angular"))
               if key in v]
    if momenta and all((m["scene"], m["window"]) == (momenta[0][1]["scene"], momenta[0][1]["window"])
                       for _, m in momenta):
        where = momenta[0][1]
        parts.append("momentum " + ", ".join(f"{word} {m['value']:.1g}" for word, m in momenta)
                     + f" ({where['scene']}, {where['window']:.3g} s)")
    else:
        parts += [f"{word} momentum {m['value']:.1g} ({m['scene']}, {m['window']:.3g} s)" for word, m in momenta]
    return "; ".join(parts) or "no conservative scene run"


def stability_rows(ctx, engine):
    """The stability headlines' rows of this engine: its own name, or mysim's integrators."""
    rows = []
    for scene in ctx.manifest.get("headlines", {}).get("stability", []):
        for e in scene["engines"]:
            name = e["engine"]
            if name == engine or name.startswith(engine + ":") or name.startswith(engine + " ("):
                rows.append((scene, e))
    return rows


def stability_cell(ctx, engine):
    rows = stability_rows(ctx, engine)
    if not rows:
        return "not mapped"
    ratios = [(e["ratio_worst"], e["ratio_best"]) for _, e in rows if "ratio_worst" in e]
    untheorised = [e["h_w_max_worst"] for _, e in rows if "ratio_worst" not in e and "h_w_max_worst" in e]
    stable = sorted({e["engine"].removeprefix(engine + ":") for _, e in rows
                     if e["stable_at_max"] == e["cells"] and e["cells"]})
    parts = []
    if ratios:
        parts.append(f"x{min(r[0] for r in ratios):.2f} to x{max(r[1] for r in ratios):.2f} of theory")
    if untheorised:
        parts.append(f"h w_max from {min(untheorised):.2g} (no theory)")
    if stable:
        who = "" if stable == [engine] else ", ".join(stable) + ": "
        parts.append(f"{who}stable at every step tried")
    scenes = sorted({s["scene"] for s, _ in rows})
    return "; ".join(parts) + f" [{', '.join(scenes)}]"


def wins(ctx, engine):
    """Each sweep scene where this engine (mysim: any integrator) is the cheapest under the bound."""
    found = []
    for entry in ctx.manifest.get("recommendations", []):
        with open(entry["path"]) as f:
            rec = json.load(f)
        for r in rec["recommendations"]:
            best = r.get("best")
            if best and best["engine"] == engine:
                scene = os.path.basename(r["scene"]).removesuffix(".json")
                how = f"{best['integrator']}, " if best.get("integrator", "-") != "-" else ""
                found.append(f"{scene} x{r['stiffness_scale']:g}: {how}{best['dt'] * 1e3:.3g} ms")
    return "; ".join(dict.fromkeys(found)) or "none"


def verdict_rows(ctx):
    rows = []
    for v in ctx.manifest.get("headlines", {}).get("verdicts", []):
        engine = v["engine"]
        cells = [engine, trust_cell(ctx, v), bias_cell(ctx, v), conservation_cell(v), stability_cell(ctx, engine),
                 wins(ctx, engine)]
        rows.append(["\n".join(textwrap.wrap(text, width, break_on_hyphens=False)) or ""
                     for text, (_, _, width) in zip(cells, COLUMNS)])
    return rows


def draw_verdict_table(fig, rows, top, height):
    ax = fig.add_axes((0.03, top - height, 0.94, height))
    ax.axis("off")
    header = ["\n".join(textwrap.wrap(name, width)) for name, _, width in COLUMNS]
    lines = [max(c.count("\n") + 1 for c in row) for row in [header] + rows]
    table = ax.table(cellText=rows, colLabels=header, colWidths=[w for _, w, _ in COLUMNS],
                     loc="upper left", cellLoc="left")
    table.auto_set_font_size(False)
    table.set_fontsize(6.8)
    unit = 1.0 / (sum(lines) + 0.5)
    for (r, _), cell in table.get_celld().items():
        cell.PAD = 0.02
        cell.set_height(unit * lines[r])
        cell.set_edgecolor("0.8")
        if r == 0:
            cell.set_text_props(weight="bold")
            cell.set_facecolor("#eeeeee")
    return sum(lines)


def biases(gate):
    """The checks whose bound allows a known bias: 'engine, scene: bias (measured m of bound b)'."""
    found = []
    for c in gate["checks"]:
        if c.get("known_bias"):
            scene = os.path.basename(c["scene"]).removesuffix(".json")
            unit = "" if c.get("unit", "") in ("", "1") else " " + c["unit"]
            measured = "n/a" if c["measured"] is None else f"{c['measured']:.2g}{unit}"
            found.append(f"{' ~ '.join(c['engines'])}, {scene}: {c['known_bias']} "
                         f"(measured {measured} within the bound {c['bound']:.2g}{unit})")
    return found


def draw_gates(fig, ctx, gate, y):
    if not gate:
        fig.text(0.03, y, f"Tolerance gates: not run (what makes them: {ctx.page_of('missing_inputs')})",
                 fontsize=10, weight="bold")
        return
    passed = sum(c["passed"] for c in gate["checks"])
    colour = "#2a7a2a" if passed == len(gate["checks"]) else "#b00000"
    known = biases(gate)
    fig.text(0.03, y, f"Tolerance gates: {passed} of {len(gate['checks'])} passed; {len(known)} of the bounds "
             f"allow a known bias [{ctx.page_of('gates_1')}]", fontsize=10, weight="bold", color=colour)
    half = (len(known) + 1) // 2
    for x, part in ((0.03, known[:half]), (0.5, known[half:])):
        text = "\n".join("\n".join(textwrap.wrap("- " + b, 105, subsequent_indent="  ")) for b in part)
        fig.text(x, y - 0.025, text, fontsize=6.5, va="top")


def draw(fig, ctx):
    rows = verdict_rows(ctx)
    if not rows:
        return ["No suite comparison in the results: no verdicts."]
    height = min(0.5, 0.024 * (sum(max(c.count("\n") + 1 for c in r) for r in rows) + 4))
    draw_verdict_table(fig, rows, 0.89, height)
    gate = None
    if ctx.manifest.get("gate"):
        with open(ctx.manifest["gate"]) as f:
            gate = json.load(f)
    y = 0.89 - height - 0.03
    draw_gates(fig, ctx, gate, y)
    return []


def trust_counts(ctx):
    """'engine trusted/scenes' for each engine held to a closed form (springcheck report's verdicts):
    the answer page 1 and the closed-form page both give in their titles."""
    return [f"{v['engine']} {v['closed_forms']['trusted']}/{v['closed_forms']['scenes']}"
            for v in ctx.manifest.get("headlines", {}).get("verdicts", []) if v.get("closed_forms")]


def title(ctx):
    """The answer: how many closed forms each engine meets to 1 %."""
    parts = trust_counts(ctx)
    if not parts:
        return "springcheck: do the engines agree, where do they break, what should I run?"
    return "Which engine can I trust? Closed forms met to 1 %: " + ", ".join(parts)


def page(ctx):
    return Page("dashboard", title(ctx),
                "One row per engine over the suite's scenes (mysim at each scene's own integrator). Trusted for: "
                "the closed forms it meets to 1 % of the exact value (a position or distance error over the "
                "run, relative to the exact value; 1 mm where the exact value is 0: a body that must not move). "
                "Energy drift: relative to E_ref, the larger of |E(0)| and the peak kinetic energy, on scenes "
                "nothing drives, damps or touches. Stability: measured / theory (or h w_max where no linear "
                "theory exists) over every cell of the maps; a scene's name in brackets. A gate that passes is "
                "not a verdict of accuracy: the bounds listed under the gate count allow a known bias.", draw)
