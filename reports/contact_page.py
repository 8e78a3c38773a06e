"""Contact physics in every engine: friction against the rigid block's closed form, and whether a
cloth passes through itself (docs/contact.md)."""
import json
import textwrap

from report_style import Page

# A friction run holds Coulomb's law when it is within 1 % of the block's distance (the issue's
# bound for a slide), or within 1e-6 m of no motion when the block sticks.
SLIDE_RELATIVE, STUCK = 0.01, 1e-6


def contact_of(model):
    """What contact physics a suite scene asks for: 'friction mu_s/mu_k' and 'self-collision T mm'."""
    parts = []
    for c in model.get("colliders", []):
        f = c.get("friction")
        if f:
            parts.append(f"{c['type']} mu {f['static']:g}/{f['kinetic']:g}")
    if model.get("self_collision"):
        parts.append(f"self-collision {1e3 * model['self_collision']['thickness']:g} mm")
    return " + ".join(parts)


def crossings_of(e):
    """'N cross, D mm' (a chain: 'nearest D mm'), or None without a self-contact metric."""
    crossings, nearest = e.get("self_intersections"), e.get("self_distance_min")
    if crossings is None:
        return f"nearest {1e3 * nearest:.2g} mm" if nearest is not None else None
    return f"{crossings:g} cross" + (f", {1e3 * nearest:.2g} mm" if nearest is not None else "")


def cell_of(e, has_self):
    """(text, holds) for one engine on one scene: self-collision judged by its crossings (a
    chain: held when its links stayed apart), friction by the block's closed form where the scene
    has it; otherwise the crossings shown, not judged (holds None)."""
    if e.get("blowup_time") is not None:
        return "blew up", False
    error, form = e.get("closed_form_error"), e.get("closed_form")
    if has_self:
        crossings = e.get("self_intersections")
        return crossings_of(e) or "-", (crossings == 0 if crossings is not None else e.get("self_distance_min") is not None)
    if error is not None and form:
        exact = form["exact"]
        return f"{error:.2g} m", error <= (SLIDE_RELATIVE * exact if exact > 0 else STUCK)
    return crossings_of(e) or "-", None


def rows_of(m):
    """(scene, contact, {engine: (text, holds)}) for each suite scene with friction or self-collision."""
    rows = []
    for c in m["comparisons"]:
        if c["group"] != "suite":
            continue
        with open(c["folder"] + "/comparison.json") as f:
            j = json.load(f)
        contact = contact_of(j.get("model", {}))
        if not contact:
            continue
        has_self = bool(j.get("model", {}).get("self_collision"))
        cells = {e["engine"]: cell_of(e, has_self) for e in j["engines"]}
        for r in j.get("refused", []):
            cells.setdefault(r["engine"], ("refused", None))
        rows.append((c["scene"], contact, cells))
    return rows


def draw_table(fig, rows):
    engines = sorted({e for _, _, cells in rows for e in cells})
    ax = fig.add_axes((0.04, 0.12, 0.92, 0.72))
    ax.axis("off")
    text = [[scene, contact] + [cells.get(e, ("", None))[0] for e in engines] for scene, contact, cells in rows]
    table = ax.table(cellText=text, colLabels=["scene", "contact"] + engines, loc="upper center", cellLoc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(7.5)
    fixed = [0.19, 0.19]
    for (r, col), cell in table.get_celld().items():
        cell.set_width(fixed[col] if col < len(fixed) else (1 - sum(fixed)) / max(len(engines), 1))
        cell.set_edgecolor("0.85")
        if r == 0:
            cell.set_text_props(weight="bold")
            cell.set_facecolor("#eeeeee")
        elif col >= 2:
            holds = rows[r - 1][2].get(engines[col - 2], ("", None))[1]
            if holds is not None:
                cell.set_facecolor("#e3f2e3" if holds else "#f8dcdc")
    table.scale(1, 1.6)


def pages(m):
    rows = rows_of(m)
    if not rows:
        return []
    judged = [holds for _, _, cells in rows for _, holds in cells.values() if holds is not None]
    held = sum(judged)

    def draw(fig, ctx):
        draw_table(fig, rows)
        return []

    caption = textwrap.dedent(f"""\
        Friction scenes: each engine's error against the rigid block's closed form (a body at rest on
        an incline sticks when tan(theta) <= mu_s, slides at g (sin(theta) - mu_k cos(theta)), stops
        after v0^2 / (2 mu_k g)); green within {SLIDE_RELATIVE:.0%} of the distance, or within
        {STUCK:g} m of none when it sticks. Self-collision scenes: the most crossing triangle pairs
        in any frame ('cross', green at 0) and the nearest a node came to a triangle not around it
        (a chain: two links). A scene with neither (a fold without self-collision) shows its crossings
        uncoloured, to be read against its twin with self-collision. 'refused': the engine cannot apply that contact (Bullet has one
        friction coefficient and no chain self-collision; the classic solver no self-collision).
        bullet-classic's friction damps velocity rather than following Coulomb (docs/reference.md)."""
                               ).replace("\n", " ")
    title = f"Contact: {held} of {len(judged)} engine runs follow Coulomb's law or never cross themselves"
    return [Page("contact", title, caption, draw)]
