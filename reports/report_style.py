"""The report's look, in one place: page size and frame, and the style table that gives every
series (engine, or mysim with an integrator) one colour and marker on every page."""
import csv
import math

# Every page is A4 landscape.
PAGE_SIZE = (11.69, 8.27)
# Where a page's figure goes (left, bottom, right, top in figure fractions): the title above,
# the caption and the stamp below.
PLOT_RECT = (0.06, 0.22, 0.97, 0.88)

# The built-in series' styles, dealt in the order the manifest lists them ("series", from the
# C++ catalogues): mysim's integrators from the first palette (they keep their colours whatever
# engine name they come under, "mysim" with the scene's integrator or "mysim:NAME"), the other
# built-in engines (Bullet's) from the second, set apart by their markers (crosses and stars).
MYSIM_PALETTE = [("#d62728", "v"), ("#ff7f0e", "<"), ("#1f77b4", "o"), ("#2ca02c", "s"),
                 ("#17becf", "D"), ("#9467bd", "^"), ("#8c564b", "p"), ("#393b79", "d"),
                 ("#637939", "H"), ("#843c39", ">"), ("#7b4173", "8"), ("#3182bd", "<")]
ENGINE_PALETTE = [("#bcbd22", "X"), ("#e377c2", "P"), ("#7f7f7f", "*"), ("#9c9ede", "x"),
                  ("#e7969c", "+")]
# The user's own engines, in the order of their names (the same in every page of one report).
EXTERNAL_STYLES = [("#000000", "h"), ("#a0522d", "8"), ("#006400", "d"), ("#00008b", ">"),
                   ("#8b008b", "H"), ("#b8860b", "1")]
# Variants of one series (dopri5's tolerances, bullet-classic's iteration counts).
LINESTYLES = ["-", "--", ":", "-."]


def builtin_styles(series):
    """key -> (colour, marker) for the manifest's built-in series, each kind from its palette."""
    styles, dealt = {}, {"mysim": 0, "other": 0}
    for s in series:
        kind = "mysim" if s["kind"] == "mysim" else "other"
        palette = MYSIM_PALETTE if kind == "mysim" else ENGINE_PALETTE
        styles[s["key"]] = palette[dealt[kind] % len(palette)]
        dealt[kind] += 1
    return styles


class StyleTable:
    def __init__(self, series=(), external_names=()):
        self.builtin = builtin_styles(series)
        self.external = {name: EXTERNAL_STYLES[i % len(EXTERNAL_STYLES)]
                         for i, name in enumerate(sorted(set(external_names) - set(self.builtin)))}

    def key(self, engine, integrator=""):
        """The style key of a series: 'mysim:rk4' for mysim (whatever its name), else the engine."""
        if engine == "mysim" and integrator:
            return f"mysim:{integrator}"
        if engine in ("mysim", "") and not integrator:
            return "mysim:rk4"
        return engine

    def key_of(self, engine):
        """The style key of a manifest engine entry (name and what stepped it)."""
        return self.key(engine["name"], engine["integrator"])

    def of(self, key):
        """(colour, marker) of a series key; unknown keys get the next external style."""
        if key in self.builtin:
            return self.builtin[key]
        if key not in self.external:
            self.external[key] = EXTERNAL_STYLES[len(self.external) % len(EXTERNAL_STYLES)]
        return self.external[key]

    def line(self, key, variant=0):
        colour, marker = self.of(key)
        return dict(color=colour, marker=marker, linestyle=LINESTYLES[variant % len(LINESTYLES)],
                    markersize=5, lw=1.3)


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def wrap_setup(label, width=26):
    """An engine or integrator with its parameters (mysim:xpbd:substeps=1:iterations=10:tolerance=0)
    on lines of at most `width` characters, broken after a ':' (never inside a parameter), so a
    legend or a row name stays on the page."""
    parts = label.split(":")
    if len(label) <= width or len(parts) <= 2:
        return label
    lines, line = [], ":".join(parts[:2])
    for part in parts[2:]:
        if len(line) + 1 + len(part) > width:
            lines.append(line + ":")
            line = part
        else:
            line += ":" + part
    return "\n".join(lines + [line])


def window_text(sweep):
    """The time a sweep's errors are over (its runs' simulated time), for captions and titles."""
    window = (sweep or {}).get("window")
    return f"over the first {window:.3g} s of the scene" if window else "over the sweep's runs"


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def coincident(series, rtol=0.01):
    """Pairs (a, b) of series whose points agree to rtol at every x: on a log axis 1 % is inside
    the line's width, so b, drawn under a, would vanish. series: label -> sorted list of (x, y)."""
    labels = sorted(series)
    pairs = []
    for i, a in enumerate(labels):
        for b in labels[i + 1:]:
            pa, pb = series[a], series[b]
            if len(pa) == len(pb) and pa and all(
                    math.isclose(xa, xb, rel_tol=rtol) and math.isclose(ya, yb, rel_tol=rtol, abs_tol=1e-300)
                    for (xa, ya), (xb, yb) in zip(pa, pb)):
                pairs.append((a, b))
    return pairs


def coincident_groups(pairs):
    """The pairs joined into groups of series that coincide, transitively, each sorted."""
    groups = []
    for a, b in pairs:
        joined = [g for g in groups if a in g or b in g]
        merged = {a, b}.union(*joined)
        groups = [g for g in groups if g not in joined] + [merged]
    return [sorted(g) for g in groups]


def coincidence_note(group):
    return ", ".join(group[:-1]) + f" and {group[-1]} coincide."


def draw_coincidences(ax, pairs, styles_of, markers=True):
    """Redraws the hidden member of each coinciding pair as larger hollow markers (or, for dense
    time series, a wide translucent band), so both show, and returns the notes saying so."""
    if not pairs:
        return []
    groups = coincident_groups(pairs)
    notes = [coincidence_note(g) for g in groups]
    pairs = [(None, b) for g in groups for b in g[1:]]
    # Said in the caption (the notes), not in a box on the axes, where it would cover data.
    how = "hollow markers" if markers else "a wide pale band"
    notes = [n.removesuffix(".") + f" (drawn as {how}: the series underneath)." for n in notes]
    for i, (_, b) in enumerate(pairs):
        xs, ys, kw = styles_of(b)
        if markers:
            ax.plot(xs, ys, linestyle="none", marker=kw["marker"], markersize=10 + 4 * i, markerfacecolor="none",
                    markeredgecolor=kw["color"], markeredgewidth=1.4)
        else:
            ax.plot(xs, ys, color=kw["color"], lw=6 + 5 * i, alpha=0.35, zorder=1 - 0.01 * i)
    return notes


class Page:
    """One page: a key (its PNG's name, and how other pages refer to it), the question it answers
    (its title), how to read it (its caption), and draw(fig, ctx), which may return notes to add
    to the caption (what it found while drawing, e.g. series that coincide), and the command that
    makes the table it draws (printed on the page, so a figure says how to reproduce it)."""

    def __init__(self, key, title, caption, draw, command=None):
        self.key, self.title, self.caption, self.draw, self.command = key, title, caption, draw, command


def plot_area(fig, rows=1, cols=1, right=None, top=None, left=None, **kw):
    """A grid of axes inside the page's plot rectangle (`right`, `top`: leave room for a legend;
    `left`: for long tick labels)."""
    default_left, bottom, default_right, default_top = PLOT_RECT
    return fig.add_gridspec(rows, cols, left=left or default_left, bottom=bottom,
                            right=right or default_right,
                            top=top or default_top, **kw)
