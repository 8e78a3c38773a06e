"""Page 2: one line per engine (what it agrees with, where it leaks energy or momentum, its worst
closed-form error) and one picture ranking the engines scene by scene. Every number comes from
`springcheck report` (manifest headlines "verdicts" and "ranking"); this only words and draws."""
import math
import textwrap

import numpy as np
from matplotlib import colors
from matplotlib.patches import Rectangle

from report_style import Page


def verdict_line(v):
    """One engine's verdict, in words, from its numbers."""
    parts = []
    if "closest" in v:
        c = v["closest"]
        plural = "s" if c["scenes"] != 1 else ""
        parts.append(f"closest to {c['engine']} on settled cloths (median {c['median'] * 1e3:.2g} mm over "
                     f"{c['scenes']} cloth{plural})")
    if "closed_form" in v:
        parts.append(f"worst closed-form error {v['closed_form']['value']:.2g} ({v['closed_form']['scene']})")
    if "energy_drift" in v:
        e = v["energy_drift"]
        word = "keeps its energy" if e["value"] < 0.01 else "drifts in energy" if e["value"] < 0.5 else "loses or gains energy"
        parts.append(f"{word}: worst drift {e['value']:.2g} of E_ref ({e['scene']})")
    momenta = [(k, v[k]) for k in ("linear_momentum", "angular_momentum") if k in v]
    if momenta:
        worst = max(momenta, key=lambda kv: kv[1]["value"])
        word = "conserves momentum" if worst[1]["value"] < 1e-6 else "loses momentum"
        parts.append(f"{word}: worst {worst[0].replace('_', ' ')} drift {worst[1]['value']:.1g} ({worst[1]['scene']})")
    for rule in v.get("step_rules", [])[:1]:  # the first mapped scene (the main job's chain_swing)
        if "theory_h" in rule and "w_max" in rule:
            c = rule["theory_h"] * rule["w_max"]
            measured = f", measured {rule['h_stable'] * 1e3:.3g} ms" if rule["status"] == "bracketed" else ""
            parts.append(f"step rule on {rule['scene']}: h < {c:.3g} / w_max = {c:.3g} / {rule['w_max']:.4g} rad/s "
                         f"= {rule['theory_h'] * 1e3:.3g} ms{measured}")
        elif rule["status"] == "stable-at-max":
            parts.append(f"on {rule['scene']}: stable at every step tried (up to h w_max = 30)")
        elif rule["status"] == "bracketed" and "h_stable" in rule and "w_max" in rule:
            parts.append(f"largest stable step on {rule['scene']}: {rule['h_stable'] * 1e3:.3g} ms "
                         f"(h w_max = {rule['h_stable'] * rule['w_max']:.3g}; no linear theory for its scheme)")
    if v.get("not_ok"):
        parts.append(f"did not finish cleanly on {', '.join(v['not_ok'])}")
    return f"{v['engine']}: " + "; ".join(parts) + "."


def draw(fig, ctx):
    h = ctx.manifest.get("headlines", {})
    verdicts, scenes = h.get("verdicts", []), h.get("ranking", [])
    y = 0.875
    for v in verdicts:
        wrapped = textwrap.wrap(verdict_line(v), 120)
        fig.text(0.05, y, "\n".join(wrapped), fontsize=7.5, va="top")
        y -= 0.017 * len(wrapped) + 0.006
    engines = [v["engine"] for v in verdicts]
    if not scenes or not engines:
        return ["No suite comparison in the results: nothing to rank."]
    values = np.full((len(engines), len(scenes)), np.nan)
    for j, s in enumerate(scenes):
        for i, e in enumerate(engines):
            if e in s["values"] and s["values"][e] > 0:
                values[i, j] = s["values"][e]
    ax = fig.add_axes((0.15, 0.36, 0.78, max(0.12, y - 0.4)))
    finite = values[np.isfinite(values)]
    norm = colors.LogNorm(vmin=max(finite.min(), 1e-16), vmax=max(finite.max(), 1e-15))
    image = ax.imshow(np.ma.masked_invalid(values), cmap="viridis", norm=norm, aspect="auto")
    for i, e in enumerate(engines):
        for j, s in enumerate(scenes):
            if math.isfinite(values[i, j]):
                ax.text(j, i, f"{values[i, j]:.0e}", ha="center", va="center", fontsize=6.5,
                        color="white" if norm(values[i, j]) < 0.55 else "black")
            elif s["values"].get(e) == 0.0:  # the scene's reference engine, or exactly equal to it
                ax.text(j, i, "ref" if s["measure"] != "closed form" else "0", ha="center", va="center",
                        fontsize=7, color="0.3")
            if scenes[j]["not_ok"] and engines[i] in scenes[j]["not_ok"]:
                ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, fill=False, edgecolor="red", lw=1.5))
    marks = {"settled": "settled", "moving": "moving", "driven": "driven"}
    labels = [f"{s['scene']}\n{marks.get(s['state']['state'], '')}, {s['measure'].split(' vs ')[0]}" for s in scenes]
    ax.set_xticks(range(len(scenes)), labels, rotation=40, ha="right", rotation_mode="anchor", fontsize=7)
    ax.set_yticks(range(len(engines)), engines, fontsize=7.5)
    bar = fig.colorbar(image, ax=ax, shrink=0.8, pad=0.01)
    bar.set_label("error [m; the pendulum's period: relative]", fontsize=7.5)
    ax.set_title("Error against the closed form where a scene has one, else distance to its first engine (ref): "
                 "rest shape if settled, trajectory RMS if not", fontsize=8)
    return ["A blank cell: the engine refuses the scene. A red frame: the run blew up or stopped at a solver limit there. Moving and driven scenes are compared "
            "over their whole trajectory, so a chaotic one (chain_swing) ranks engines by how soon round-off "
            "grows, not by accuracy."]


def page(ctx):
    return Page("verdicts", "What is each engine like, and how do they rank scene by scene?",
                "Top: one line per engine over the suite's scenes, from the same tables as every other page: the "
                "engine it is closest to on settled cloths (mirror-aware drape), its worst closed-form error, its "
                "worst energy drift (relative to E_ref, the larger of |E(0)| and the peak kinetic energy) on a scene "
                "nothing drives or damps, its worst momentum drift on a free body. Bottom: "
                "the ranking picture, darker is closer; each column says whether the scene settled and what is "
                "measured.", draw)
