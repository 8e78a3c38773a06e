"""Every engine against every closed form the suite's scenes have, a user's engine among them."""
import json

from report_style import Page


STEPPERS = set()  # what stepped plain "mysim" on these scenes (each scene names its integrator)


def rows_of(m):
    """(scene, quantity, exact, {engine: (error, at motion floor)}) for each suite scene with one."""
    rows = []
    for c in m["comparisons"]:
        if c["group"] != "suite":
            continue
        with open(c["folder"] + "/comparison.json") as f:
            j = json.load(f)
        errors, quantity, exact = {}, None, None
        for e in j["engines"]:
            if e["engine"] == "mysim" and e.get("integrator"):
                STEPPERS.add(e["integrator"])
            form = e.get("closed_form")
            if form and e.get("closed_form_error") is not None:
                quantity, exact = form["quantity"], form["exact"]
                errors[e["engine"]] = (e["closed_form_error"], form.get("at_motion_floor", False))
        if errors:
            rows.append((c["scene"], quantity, exact, errors))
    return rows


def draw(fig, ctx):
    rows = rows_of(ctx.manifest)
    if not rows:
        return ["No suite scene with a closed form in the results."]
    engines = sorted({e for _, _, _, errors in rows for e in errors})
    ax = fig.add_axes((0.06, 0.3, 0.9, 0.55))
    ax.axis("off")
    def unit(quantity):  # frequencies and periods are compared relatively, shapes in metres
        return "rel" if "period" in quantity or "frequency" in quantity else "m"
    cells = []
    for scene, quantity, exact, errors in rows:
        line = [scene, quantity, f"{exact:.4g}", unit(quantity)]
        for e in engines:
            if e in errors:
                value, floor = errors[e]
                line.append(f"{value:.2g}" + (" (motion left)" if floor else ""))
            else:
                line.append("")
        cells.append(line)
    table = ax.table(cellText=cells, colLabels=["scene", "closed form", "exact value", "error unit"] + engines,
                     loc="upper center", cellLoc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    table.scale(1, 1.6)
    for (r, _), cell in table.get_celld().items():
        cell.set_edgecolor("0.85")
        if r == 0:
            cell.set_text_props(weight="bold")
            cell.set_facecolor("#eeeeee")
    stepped = f"mysim: the integrator each scene names ({', '.join(sorted(STEPPERS))} here). " if STEPPERS else ""
    return [stepped + "'(motion left)': the nodes still moved by a tenth or more of the error over the run's last tenth, "
            "so the error is the motion left at the end, the same for every engine, not its accuracy."]


def page():
    return Page("closed_forms", "How far is each engine from the exact answers?",
                "Each suite scene with a closed form, and each engine's error against it: the circle (max distance "
                "from the exact circle over the run), the pendulum (relative error of its period against the "
                "rigid pendulum's elliptic-integral period), the hanging chain at rest (max node distance from "
                "y_j = -[j L0 + (m g / k) j (2N - j + 1) / 2]). Your own engine is a column like any other; its "
                "gate is in the tolerances file.", draw)
