"""Every gate in a table, on pages of their own (page 1 gives their count and the known biases
their bounds allow)."""
import json
import os
import textwrap

from report_style import Page

# Lines of gate table a page holds (a check takes one line per line of its wrapped reason): the
# table fills the plot area (0.22 to 0.88 of 8.27 in), about 10 pt a line at the table's 7 pt.
MORE_PAGE_LINES = 40
# Characters per table line at the table's 7 pt (about 4 pt a character): the reason column is
# 0.40 and the engines column 0.16 of the table's 0.95 of an 842 pt page (the scene column 0.13: a
# scene name such as capstan_three_eighths_turn whole).
REASON_WIDTH = 79
ENGINES_WIDTH = 30


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
                     colWidths=[0.035, 0.13, 0.16, 0.125, 0.05, 0.045, 0.055, 0.40], loc="upper left",
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


def pages(ctx):
    m = ctx.manifest
    result = []
    if m.get("gate"):
        with open(m["gate"]) as f:
            checks = json.load(f)["checks"]
        rows, failed, lines = gate_rows(checks)
        passed = sum(c["passed"] for c in checks)
        answer = f"{passed} of {len(checks)} gate checks hold" + (
            "" if passed == len(checks) else f": {len(checks) - passed} fail (listed first)")
        for n, part in enumerate(paginate(rows, failed, lines, MORE_PAGE_LINES, MORE_PAGE_LINES)):
            result.append(Page(f"gates_{n + 1}", answer + (" (continued)" if n else ""),
                               "Every check of the tolerances file, failures first: the engines it measures (mysim "
                               "with the integrator the scene names), the metric, its unit, the bound, the measured "
                               "value and why the bound is that number (compare/tolerances.json).",
                               lambda fig, ctx, part=part: draw_gate_table(fig, *part, 0.88, 0.66) or []))
    return result
