"""Page 1: the answers at a glance (gates, the recommendation, where each engine goes unstable,
the largest disagreement), each with the page it comes from; every gate in a table."""
import json
import os
import textwrap
from collections import defaultdict

from report_style import Page

FIRST_PAGE_GATES = 22
MORE_PAGE_GATES = 38


def short(text, width):
    return text if len(text) <= width else text[:width - 1] + "…"


def gate_rows(checks):
    rows, failed = [], []
    for c in sorted(checks, key=lambda c: c["passed"]):  # failures first
        measured = "n/a" if c["measured"] is None else f"{c['measured']:.3g}"
        rows.append(["PASS" if c["passed"] else "FAIL", os.path.basename(c["scene"]).removesuffix(".json"),
                     " ~ ".join(c["engines"]), c["metric"], f"{c['bound']:.3g}", measured,
                     short(c["problem"] or c["why"], 80)])
        failed.append(not c["passed"])
    return rows, failed


def draw_gate_table(fig, rows, failed, top, height):
    ax = fig.add_axes((0.04, top - height, 0.93, height))
    ax.axis("off")
    if not rows:
        return
    table = ax.table(cellText=rows, colLabels=["", "scene", "engines", "metric", "bound", "measured",
                                               "why this bound (or what went wrong)"],
                     colWidths=[0.04, 0.11, 0.18, 0.145, 0.05, 0.06, 0.415], loc="upper left",
                     cellLoc="left")
    table.auto_set_font_size(False)
    table.set_fontsize(6.6)
    for (r, col), cell in table.get_celld().items():
        cell.PAD = 0.03  # matplotlib's default indents a wide column's text by a tenth of it
        cell.set_height(min(1.0 / (len(rows) + 1), 0.06))
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
        lines.append((f"Largest disagreement between engines on a cloth's last frame: {worst['value'] * 1e3:.3g} mm "
                      f"(max node distance) between {worst['a']} and {worst['b']} on {worst['scene']}.",
                      f"drape_{worst['group'].replace('/', '_')}_{worst['scene']}"))
    for body in h.get("momentum", []):
        parts = [f"{kind} {body[key]['value']:.2g} ({body[key]['engine']})"
                 for kind, key in (("linear", "linear_momentum_drift"), ("angular", "angular_momentum_drift"))
                 if key in body]
        lines.append((f"Momentum on {body['scene']} (a free body), worst relative drift: " + ", ".join(parts) + ".",
                      None))
    return lines


def stability_summary(ctx):
    """Per scene stability table: engine -> 'worst h w_max (median; x worst measured/theory)' at the
    lowest mass ratio mapped, as `springcheck report` summarised it."""
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
                text = f"{e['h_w_max_worst']:.3g} ({e['h_w_max_median']:.3g})"
                if "ratio_worst" in e:
                    text += f" x{e['ratio_worst']:.2f}"
            cells[e["engine"]][scene["scene"]] = text
    return columns, cells


def draw_dashboard(fig, ctx, rows, failed):
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
        fig.text(0.04, y - 0.025, f"from {gate['tolerances']}; every check in the table below", fontsize=7,
                 color="0.35")
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
        ax = fig.add_axes((0.68, 0.6, 0.29, 0.3))
        ax.axis("off")
        engines = sorted(cells)
        table = ax.table(cellText=[[cells[e].get(s, "") for s in columns] for e in engines],
                         rowLabels=engines, colLabels=columns, loc="upper right", cellLoc="center")
        table.auto_set_font_size(False)
        table.set_fontsize(6.5)
        for cell in table.get_celld().values():
            cell.set_height(0.9 / (len(engines) + 1))
            cell.set_edgecolor("0.85")
        keys = ", ".join(ctx.page_of(f"stability_{s}") for s in columns)
        ax.set_title(f"Where each engine goes unstable: h w_max at its largest stable step,\n"
                     f"worst cell (median), x worst measured / theory [{keys}]", fontsize=7.5, x=0.3)
    top = min(y, 0.58) - 0.01
    draw_gate_table(fig, rows, failed, top, top - 0.19)
    return []


def pages(ctx):
    m = ctx.manifest
    rows, failed = [], []
    if m.get("gate"):
        with open(m["gate"]) as f:
            rows, failed = gate_rows(json.load(f)["checks"])
    first, rest = rows[:FIRST_PAGE_GATES], rows[FIRST_PAGE_GATES:]
    result = [Page("dashboard", "springcheck: do the engines agree, where do they break, what should I run?",
                   "Headlines from the pages named in brackets. The gate table lists every bound CI holds the "
                   "engines to, failures first, with the measured value and why the bound is that number "
                   "(compare/tolerances.json).",
                   lambda fig, ctx: draw_dashboard(fig, ctx, first, failed[:FIRST_PAGE_GATES]))]
    for n in range(0, len(rest), MORE_PAGE_GATES):
        part, part_failed = rest[n:n + MORE_PAGE_GATES], failed[FIRST_PAGE_GATES + n:FIRST_PAGE_GATES + n + MORE_PAGE_GATES]
        result.append(Page(f"gates_{n // MORE_PAGE_GATES + 2}", "Tolerance gates (continued)",
                           "The rest of the gate table of page 1.",
                           lambda fig, ctx, part=part, part_failed=part_failed:
                           draw_gate_table(fig, part, part_failed, 0.9, 0.68) or []))
    return result
