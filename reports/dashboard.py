"""Page 1: the answers at a glance (gates, the recommendation, where each engine goes unstable,
the largest disagreement), each with the page it comes from; every gate in a table."""
import json
import os
import textwrap
from collections import defaultdict

import numpy as np

from report_style import Page, number, read_csv

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
    # Settled shapes only (the cloths, which have drape pages): a swinging chain's last frames part
    # by chaos, not by disagreement.
    worst = None
    for c in m["comparisons"]:
        if c["group"] == "energy" or not c.get("pair_metrics") or c.get("model", {}).get("kind") != "cloth":
            continue
        for p in read_csv(c["pair_metrics"]):
            value = number(p.get("drape_max"))
            if value is not None and (worst is None or value > worst[0]):
                worst = (value, p["a"], p["b"], c)
    if worst:
        value, a, b, c = worst
        lines.append((f"Largest disagreement between engines on a cloth's last frame: {value * 1e3:.3g} mm "
                      f"(max node distance) between {a} and {b} on {c['scene']}.",
                      f"drape_{c['group'].replace('/', '_')}_{c['scene']}"))
    for c in m["comparisons"]:
        if c["group"] != "suite":
            continue
        with open(os.path.join(c["folder"], "comparison.json")) as f:
            free = [e for e in json.load(f)["engines"] if e.get("linear_momentum_drift") is not None]
        if free:
            worst_e = max(free, key=lambda e: max(e["linear_momentum_drift"], e["angular_momentum_drift"]))
            lines.append((f"Momentum on {c['scene']} (a free body): worst drift {worst_e['engine']}, linear "
                          f"{worst_e['linear_momentum_drift']:.2g}, angular {worst_e['angular_momentum_drift']:.2g} "
                          "(relative).", None))
    return lines


def stability_summary(ctx):
    """Per scene stability table: engine -> 'h w_max (x measured/theory)' at mass ratio 1."""
    columns, cells = [], defaultdict(dict)
    for entry in ctx.manifest["stability"]["scenes"]:
        rows = read_csv(entry["path"])
        ratio = min(number(r["mass_ratio"]) for r in rows)
        columns.append(entry["scene"])
        groups = defaultdict(list)
        for r in rows:
            if number(r["mass_ratio"]) == ratio:
                groups[r["engine"] + (f" ({r['classic_iterations']})" if r["classic_iterations"] else "")].append(r)
        for engine, mine in groups.items():
            found = [r for r in mine if r["status"] in ("bracketed", "stable-at-max")]
            if any(r["status"] == "refused" for r in mine):
                text = "refuses"
            elif not found:
                text = "never stable"
            elif all(r["status"] == "stable-at-max" for r in found):
                text = "stable at all"
            else:
                hw = np.median([number(r["h_w_max"]) for r in found if r["status"] == "bracketed"])
                ratios = [number(r["ratio"]) for r in found if number(r["ratio"])]
                text = f"{hw:.3g}" + (f" (x{np.median(ratios):.2f})" if ratios else "")
            cells[engine][entry["scene"]] = text
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
        ax.set_title(f"Where each engine goes unstable: h w_max at\nits largest stable step "
                     f"(x measured / theory) [{keys}]", fontsize=7.5, x=0.3)
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
