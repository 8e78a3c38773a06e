"""Every engine against every closed form the suite's scenes have, a user's engine among them."""
import json
import textwrap

import front_page
from report_style import Page


STEPPERS = set()  # what stepped plain "mysim" on these scenes (each scene names its integrator)


WITHOUT = {}  # reason -> scenes: suite scenes with no closed form, grouped by why


def rows_of(m):
    """(scene, quantity, exact, unit, {engine: (error, at motion floor)}) for each suite scene with one.
    An engine that blew up on such a scene gets the text "blew up" instead of an error."""
    rows = []
    WITHOUT.clear()
    for c in m["comparisons"]:
        if c["group"] != "suite":
            continue
        with open(c["folder"] + "/comparison.json") as f:
            j = json.load(f)
        errors, quantity, exact, why_not, unit = {}, None, None, None, "m"
        for e in j["engines"]:
            if e["engine"] == "mysim" and e.get("integrator"):
                STEPPERS.add(e["integrator"])
            form = e.get("closed_form")
            if form and e.get("closed_form_error") is not None:
                quantity, exact, unit = form["quantity"], form["exact"], form.get("unit", "m")
                errors[e["engine"]] = (e["closed_form_error"], form.get("at_motion_floor", False))
            elif e.get("blowup_time") is not None:
                errors[e["engine"]] = ("blew up", False)
            elif e.get("no_closed_form"):
                why_not = e["no_closed_form"]
        for r in j.get("refused", []):
            errors.setdefault(r["engine"], ("refused", False))
        if quantity is not None:
            rows.append((c["scene"], quantity, exact, unit, errors))
        elif why_not:
            WITHOUT.setdefault(why_not, []).append(c["scene"])
    return rows


def without_lines():
    """One line per reason a suite scene has no closed form, naming the scenes."""
    return [f"No closed form for {', '.join(sorted(scenes))}: {why}." for why, scenes in sorted(WITHOUT.items())]


def draw(fig, ctx):
    rows = rows_of(ctx.manifest)
    if not rows:
        return ["No suite scene with a closed form in the results."]
    engines = sorted({e for *_, errors in rows for e in errors})
    ax = fig.add_axes((0.06, 0.3, 0.9, 0.55))
    ax.axis("off")
    cells = []
    for scene, quantity, exact, unit, errors in rows:
        # The quantity's name without its particulars (a capstan's loads), which overran the cell.
        line = [scene, quantity.split(" (")[0], f"{exact:.4g}", unit]
        for e in engines:
            if e in errors:
                value, floor = errors[e]
                line.append(value if isinstance(value, str) else f"{value:.2g}" + (" *" if floor else ""))
            else:
                line.append("")
        cells.append(line)
    table = ax.table(cellText=cells, colLabels=["scene", "closed form", "exact value", "error unit"] + engines,
                     loc="upper center", cellLoc="center")
    table.auto_set_font_size(False)
    # Rows shrink as scenes are added, so the table keeps to its half of the page above the list
    # of scenes without a closed form (18 rows at 1.6 ran into it).
    crowded = len(rows) > 14
    table.set_fontsize(6.5 if crowded else 7.5)
    # Widths as fractions of the page's table: the names never cut, the engines share the rest.
    fixed = [0.16, 0.19, 0.085, 0.075]
    for (r, col), cell in table.get_celld().items():
        cell.set_width(fixed[col] if col < len(fixed) else (1 - sum(fixed)) / max(len(engines), 1))
    table.scale(1, 1.6 * min(1.0, 14 / len(rows)))
    for (r, _), cell in table.get_celld().items():
        cell.set_edgecolor("0.85")
        if r == 0:
            cell.set_text_props(weight="bold")
            cell.set_facecolor("#eeeeee")
    # Below the table, not in the caption: the scenes without a closed form and why.
    without = textwrap.wrap(" ".join(without_lines()), 190)
    fig.text(0.06, 0.29, "\n".join(without), va="top", fontsize=7.5, color="0.15")
    stepped = f"mysim: the integrator each scene names ({', '.join(sorted(STEPPERS))} here). " if STEPPERS else ""
    return [stepped + "'*': the nodes still moved by a tenth or more of the error over the run's last tenth (motion left), "
            "so the error is the motion left at the end, the same for every engine, not its accuracy. "
            "'blew up': no error is measured on a run that stopped early; 'refused': the engine cannot run the scene (its table says why)."]


def title(ctx):
    """The answer: how many closed forms each engine meets to 1 % (springcheck report's verdicts)."""
    parts = front_page.trust_counts(ctx)
    return ("How far is each engine from the exact answers? Within 1 %: " + ", ".join(parts) if parts
            else "How far is each engine from the exact answers?")


def page(ctx):
    return Page("closed_forms", title(ctx),
                "Each suite scene with a closed form (the column 'closed form' names it: the circle, the pendulum's "
                "period, the hanging chain and the two-pin catenary at rest, the damped oscillator, the taut "
                "chain's mode, the clamped strip's heavy elastica, a body on a plane with friction, the capstan), and each engine's error against it. Scenes "
                "without one are listed below with the reason. Your own engine is a column like any other; its "
                "gate is in the tolerances file.", draw)
