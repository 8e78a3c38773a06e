"""Page 1: the answers at a glance (gates, the recommendation, where each engine goes unstable,
the largest disagreement), each with the page it comes from; then every gate in a table, on pages
of their own."""
import json
import os
import textwrap
from collections import defaultdict

from report_style import Page

# Lines of gate table a page holds (a check takes one line per line of its wrapped reason): the
# table fills the plot area (0.22 to 0.88 of 8.27 in), about 10 pt a line at the table's 7 pt.
MORE_PAGE_LINES = 40
# Characters per table line at the table's 7 pt (about 4 pt a character): the reason column is
# 0.415 and the engines column 0.2 of the table's 0.95 of an 842 pt page.
REASON_WIDTH = 82
ENGINES_WIDTH = 38


def engines_text(check):
    """Each engine with what stepped it where the name alone does not say ('mysim' is the scene's
    integrator, RK4 on one scene and symplectic Euler on another)."""
    steppers = check.get("steppers") or [""] * len(check["engines"])
    parts = []
    for engine, stepper in zip(check["engines"], steppers):
        parts.append(f"{engine} [{stepper}]" if engine == "mysim" and stepper else engine)
    return " ~ ".join(parts)


def scene_text(c):
    """The scene, and the variant a check runs (resolution, step) where it names one."""
    text = os.path.basename(c["scene"]).removesuffix(".json")
    variant = [f"res {c['resolution']}"] if c.get("resolution") else []
    variant += [f"dt {c['dt']:g} s"] if c.get("dt") else []
    return text + ("\n" + ", ".join(variant) if variant else "")


def metric_text(c):
    """The metric, or its error against the physical reference where the check holds that."""
    kind = c.get("physical_error")
    return f"{c['metric']}\n{kind} error vs physics" if kind else c["metric"]


def gate_rows(checks):
    """Rows (failures first), their failed flags and their heights in lines (the reason wrapped,
    never cut)."""
    rows, failed, lines = [], [], []
    for c in sorted(checks, key=lambda c: c["passed"]):
        measured = "n/a" if c["measured"] is None else f"{c['measured']:.3g}"
        reason = c["problem"] or c["why"]
        if c.get("note"):
            reason += " Note: " + c["note"]
        wrapped = textwrap.wrap(reason, REASON_WIDTH) or [""]
        engines = textwrap.wrap(engines_text(c), ENGINES_WIDTH, break_on_hyphens=False) or [""]
        rows.append(["PASS" if c["passed"] else "FAIL", scene_text(c), "\n".join(engines),
                     metric_text(c), c.get("unit", ""), f"{c['bound']:.3g}", measured,
                     "\n".join(wrapped)])
        failed.append(not c["passed"])
        lines.append(max(len(wrapped), len(engines), 2 if c.get("physical_error") else 1))
    return rows, failed, lines


def paginate(rows, failed, lines, first, more):
    """Pages of rows holding at most `first`, then `more`, table lines each."""
    pages, start, budget = [], 0, first
    while start < len(rows):
        used, end = 0, start
        while end < len(rows) and (end == start or used + lines[end] <= budget):
            used += lines[end]
            end += 1
        pages.append((rows[start:end], failed[start:end], lines[start:end]))
        start, budget = end, more
    return pages or [([], [], [])]


def draw_gate_table(fig, rows, failed, lines, top, height):
    ax = fig.add_axes((0.03, top - height, 0.95, height))
    ax.axis("off")
    if not rows:
        return
    table = ax.table(cellText=rows, colLabels=["", "scene", "engines [integrator]", "metric", "unit", "bound",
                                               "measured", "why this bound (or what went wrong)"],
                     colWidths=[0.035, 0.09, 0.2, 0.11, 0.05, 0.045, 0.055, 0.415], loc="upper left",
                     cellLoc="left")
    table.auto_set_font_size(False)
    table.set_fontsize(7)
    unit = min(1.0 / (sum(lines) + 1), 0.05)
    for (r, col), cell in table.get_celld().items():
        cell.PAD = 0.03  # matplotlib's default indents a wide column's text by a tenth of it
        cell.set_height(unit * (1 if r == 0 else lines[r - 1]))
        cell.set_edgecolor("0.85")
        if r == 0:
            cell.set_text_props(weight="bold")
            cell.set_facecolor("#eeeeee")
        elif failed[r - 1]:
            cell.set_facecolor("#f8d0d0")
        elif col == 0:
            cell.set_text_props(color="#2a7a2a")


def headlines(ctx):
    """(text, page key) pairs, the answer first."""
    m = ctx.manifest
    lines = []
    for rec_entry in m["recommendations"]:
        with open(rec_entry["path"]) as f:
            rec = json.load(f)
        key = f"speed_accuracy_{rec_entry['sweep']}"
        for r in rec["recommendations"]:
            where = f"{os.path.basename(r['scene']).removesuffix('.json')}, stiffness x{r['stiffness_scale']:g}"
            if r["best"]:
                lines.append((f"Cheapest under {rec['max_error']:g} m of error on {where}: {r['best']['summary']}."
                              + (f" Runner-up: {r['runner_up']['summary']}." if r["runner_up"] else ""), key))
            else:
                lines.append((f"On {where}, no finished run stays under {rec['max_error']:g} m.", key))
    # The numbers below are found by `springcheck report` (manifest "headlines"); drawn here only.
    h = m.get("headlines", {})
    worst = h.get("worst_cloth_drape")
    if worst:
        mirrored = (" (to the other's mirror image: the folds buckled opposite ways)" if worst.get("mirrored")
                    else " (direct; mirror-aware: the shapes are not mirror images)")
        lines.append((f"Largest disagreement between settled cloths: {worst['value'] * 1e3:.3g} mm (max node "
                      f"distance) between {worst['a']} and {worst['b']} on {worst['scene']}, settled by "
                      f"t = {worst['state']['settled_at']:.3g} s{mirrored}.",
                      f"drape_{worst['group'].replace('/', '_')}_{worst['scene']}"))
    moving = h.get("worst_moving_cloth")
    if moving:
        state = ("driven (never at rest)" if moving["state"]["state"] == "driven"
                 else f"still moving at its last frame, t = {moving['state']['last_frame']:.3g} s")
        lines.append((f"Cloths not at rest are compared by trajectory, not by last frame: the largest RMS "
                      f"difference over the frames is {moving['value'] * 1e3:.3g} mm, between {moving['a']} and "
                      f"{moving['b']} on {moving['scene']} ({state}).", None))
    for body in h.get("momentum", []):
        parts = [f"{kind} {body[key]['value']:.2g} ({body[key]['engine']})"
                 for kind, key in (("linear", "linear_momentum_drift"), ("angular", "angular_momentum_drift"))
                 if key in body]
        lines.append((f"Momentum on {body['scene']} (a free body), worst relative drift: " + ", ".join(parts) + ".",
                      "verdicts"))
    return lines


def stability_summary(ctx):
    """Per scene stability table: engine -> 'worst h w_max [cells with a limit / cells], x worst
    measured/theory' at the lowest mass ratio mapped, as `springcheck report` summarised it."""
    columns, cells = [], defaultdict(dict)
    for scene in ctx.manifest.get("headlines", {}).get("stability", []):
        columns.append(scene["scene"])
        for e in scene["engines"]:
            if e["refused"]:
                text = "refuses"
            elif e["bracketed"] == 0 and e["stable_at_max"] == 0:
                text = "never stable"
            elif e["bracketed"] == 0:
                text = "stable at all"
            else:
                # The worst cell, and how many of the cells mapped had a limit at all (the rest were
                # stable at the largest step tried): never a median that hides either.
                text = f"{e['h_w_max_worst']:.3g} [{e['bracketed']}/{e['cells']}]"
                if "ratio_worst" in e:
                    text += f" x{e['ratio_worst']:.2f}"
            cells[e["engine"]][scene["scene"]] = text
    return columns, cells


def draw_dashboard(fig, ctx):
    m = ctx.manifest
    gate = None
    if m.get("gate"):
        with open(m["gate"]) as f:
            gate = json.load(f)
    y = 0.9
    if gate:
        passed = sum(c["passed"] for c in gate["checks"])
        colour = "#2a7a2a" if passed == len(gate["checks"]) else "#b00000"
        fig.text(0.04, y, f"Tolerance gates: {passed} of {len(gate['checks'])} passed", fontsize=12,
                 weight="bold", color=colour)
        fig.text(0.04, y - 0.025, f"from {gate['tolerances']}; every check, its unit and its reason: "
                 f"{ctx.page_of('gates_1')}", fontsize=7, color="0.35")
    else:
        fig.text(0.04, y, f"Tolerance gates: not run (what makes them: {ctx.page_of('missing_inputs')})",
                 fontsize=12, weight="bold")
    y -= 0.06
    for text, key in headlines(ctx):
        ref = f"  [{ctx.page_of(key)}]" if key else ""
        wrapped = textwrap.wrap(text + ref, 92)
        fig.text(0.04, y, "\n".join(wrapped), fontsize=7.6, va="top")
        y -= 0.0175 * len(wrapped) + 0.008
    columns, cells = stability_summary(ctx)
    if columns:
        ax = fig.add_axes((0.68, 0.57, 0.29, 0.3))  # its title under the page's reproduce line
        ax.axis("off")
        engines = sorted(cells)
        table = ax.table(cellText=[[cells[e].get(s, "") for s in columns] for e in engines],
                         rowLabels=engines, colLabels=columns, loc="upper right", cellLoc="center")
        table.auto_set_font_size(False)
        table.set_fontsize(7)
        for cell in table.get_celld().values():
            cell.set_height(0.9 / (len(engines) + 1))
            cell.set_edgecolor("0.85")
        keys = ", ".join(ctx.page_of(f"stability_{s}") for s in columns)
        ax.set_title(f"Where each engine goes unstable: h w_max at its largest stable step, worst cell\n"
                     f"[cells that went unstable / cells mapped; the rest never did], x worst measured / "
                     f"theory [{keys}]", fontsize=7, x=0.3)
    return []


def pages(ctx):
    m = ctx.manifest
    result = [Page("dashboard", "springcheck: do the engines agree, where do they break, what should I run?",
                   "Headlines from the pages named in brackets; the engines' verdicts and the ranking picture are "
                   "on the next page, every gate CI holds the engines to on the pages after it.", draw_dashboard)]
    if m.get("gate"):
        with open(m["gate"]) as f:
            rows, failed, lines = gate_rows(json.load(f)["checks"])
        for n, part in enumerate(paginate(rows, failed, lines, MORE_PAGE_LINES, MORE_PAGE_LINES)):
            result.append(Page(f"gates_{n + 1}", "Which bounds does CI hold the engines to, and do they hold?"
                               + (" (continued)" if n else ""),
                               "Every check of the tolerances file, failures first: the engines it measures (mysim "
                               "with the integrator the scene names), the metric, its unit, the bound, the measured "
                               "value and why the bound is that number (compare/tolerances.json).",
                               lambda fig, ctx, part=part: draw_gate_table(fig, *part, 0.88, 0.66) or []))
    return result
