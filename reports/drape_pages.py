"""The cloth's last frame: its shape in true proportions, the colliders under it, and where each
engine puts each node relative to the first engine; titled by whether the cloth has settled (a
last frame of a moving or driven cloth is a snapshot, not a rest shape)."""
import math
from collections import defaultdict

import numpy as np
from matplotlib import cm, colors
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import colliders as colliders_drawing
from report_style import Page, number, plot_area, read_csv


def read_faces(path):
    faces = []
    with open(path) as f:
        for line in f:
            if line.startswith("f "):
                faces.append([int(v.split("/")[0]) - 1 for v in line.split()[1:4]])
    return np.array(faces, dtype=int)


def positions(path):
    return np.array([[number(r["x"]), number(r["y"]), number(r["z"])] for r in read_csv(path)])


def equal_aspect_3d(ax, points):
    """Axes in true proportions (simulation y is drawn up)."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    span = np.maximum(hi - lo, 1e-3 * max(hi - lo))
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[2], hi[2])
    ax.set_zlim(lo[1], hi[1])
    ax.set_box_aspect((span[0], span[2], span[1]))


def state_words(state):
    """What the last frame is, from the settling metric: (title phrase, short phrase)."""
    if not state:
        return "the last frame", "last frame"
    if state["state"] == "settled":
        return f"the cloth settled by t = {state['settled_at']:.3g} s", "settled"
    if state["state"] == "driven":
        return (f"the last frame at t = {state['last_frame']:.3g} s, driven (never at rest)",
                "last frame, driven")
    return f"the last frame at t = {state['last_frame']:.3g} s, still moving", "last frame, still moving"


def drape_title(c, title_words):
    """The answer: how far apart the engines' nodes are at this frame, and whose."""
    worst = (0.0, "", "")
    for r in read_csv(c["node_distance"]) if c.get("node_distance") else []:
        worst = max(worst, (number(r["distance"]) or 0.0, r["engine"], r["reference_engine"]))
    if not worst[1]:
        return f"{c['scene']}: {title_words} (one engine: nothing to compare)"
    size = f"{worst[0]:.2g} m" if 0 < worst[0] < 1e-6 or worst[0] >= 1 else f"{worst[0] * 1e3:.3g} mm"
    return f"{c['scene']}: engines up to {size} from {worst[2]} ({worst[1]}) on {title_words}"


def comparison_page(c, state):
    colliders = c.get("model", {}).get("colliders") or []
    title_words, short_words = state_words(state)

    def draw(fig, ctx):
        runs = [e for e in c["engines"] if e.get("final_state") and e.get("final")]
        distance = defaultdict(dict)
        reference_name = runs[0]["name"]
        if c.get("node_distance"):
            for r in read_csv(c["node_distance"]):
                distance[r["engine"]][int(r["node"])] = number(r["distance"])
                reference_name = r["reference_engine"]
        reference = next(e for e in runs if e["name"] == reference_name)
        others = [e for e in runs if e["name"] in distance]
        xyz = positions(reference["final_state"])
        faces = read_faces(reference["final"])
        values = [v for d in distance.values() for v in d.values() if v and v > 0]
        # Distances all below 1e-12 m (engines equal to round-off) still get a scale, 1e-12 to 1e-11.
        low = max(min(values), 1e-12) if values else None
        norm = colors.LogNorm(vmin=low, vmax=max(max(values), 10 * low)) if values else None
        cmap = cm.viridis
        cols = 2 if len(others) > 1 else 1
        rows = max(1, math.ceil(len(others) / cols))
        grid = plot_area(fig, rows, 1 + cols, width_ratios=[2.2] + [1] * cols, wspace=0.3, hspace=0.35)
        ax = fig.add_subplot(grid[:, 0], projection="3d")
        worst = np.zeros(len(xyz))
        for d in distance.values():
            worst = np.maximum(worst, [d.get(n, 0.0) for n in range(len(xyz))])
        if norm is not None:
            face_colours = cmap(norm(np.maximum(worst[faces].mean(axis=1), norm.vmin)))
        else:
            face_colours = "lightgrey"
        mesh = Poly3DCollection(xyz[faces][:, :, [0, 2, 1]], facecolors=face_colours, edgecolors="0.35",
                                linewidths=0.15, alpha=0.95)
        ax.add_collection3d(mesh)
        equal_aspect_3d(ax, np.vstack([xyz, colliders_drawing.draw_3d(ax, colliders, xyz)]))
        ax.set_xlabel("x [m]", fontsize=8)
        ax.set_ylabel("z [m]", fontsize=8)
        ax.set_zlabel("y [m]", fontsize=8)
        ax.tick_params(labelsize=6)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):  # a short axis (a flat cloth's height) kept legible
            axis.set_major_locator(MaxNLocator(4))
        ax.set_title(f"{reference_name}'s cloth ({short_words}),\ncoloured by the largest distance of any engine",
                     fontsize=8.5)
        # The flat view that shows most: across the shape's two largest extents (from above for a
        # cloth lying on a sphere, from the front for a hanging one).
        extent = xyz.max(axis=0) - xyz.min(axis=0)
        u, v = sorted(np.argsort(extent)[1:])
        names = "xyz"
        view = "from above" if 1 not in (u, v) else "from the front" if 2 not in (u, v) else "from the side"
        for i, e in enumerate(others):
            flat = fig.add_subplot(grid[i // cols, 1 + i % cols])
            mine = positions(e["final_state"])
            d = np.array([distance[e["name"]].get(n, 0.0) for n in range(len(mine))])
            flat.scatter(mine[:, u], mine[:, v], c=np.maximum(d, norm.vmin) if norm else d, cmap=cmap,
                         norm=norm, s=10)
            colliders_drawing.draw_flat(flat, colliders, u, v)
            flat.set_aspect("equal")
            flat.set_title(f"{e['name']}: max {max(d):.2g} m", fontsize=8)
            flat.tick_params(labelsize=6)
            flat.set_xlabel(f"{names[u]} [m]", fontsize=7)
            flat.set_ylabel(f"{names[v]} [m]", fontsize=7)
        if norm is not None:
            bar = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=fig.axes, shrink=0.6,
                               location="right", pad=0.02)
            bar.set_label(f"distance of a node to {reference_name}'s [m]", fontsize=8)
        notes = [f"Right: seen {view} ({names[u]}-{names[v]})."]
        if state and state["state"] != "settled":
            notes.append("The cloth is not at rest at this frame: these distances are of a snapshot of the motion, "
                         "not of rest shapes (the trajectory difference, over every frame, is the comparison).")
        return notes + ([] if others else ["Only one engine finished: nothing to compare it with."])

    return Page(f"drape_{c['group'].replace('/', '_')}_{c['scene']}", drape_title(c, title_words),
                "Left: the last frame of the first engine in true proportions (equal axes), the colliders as "
                "wire frames where the scene has them, each triangle coloured by the largest distance any other "
                "engine's node has from this one. Right: the nodes flat, across the shape's two largest extents, one "
                "panel per engine, each node coloured by its own distance (log colour scale, shared).", draw)


def pages(manifest):
    chosen = [c for c in manifest["comparisons"] if c.get("model", {}).get("kind") == "cloth"
              and c["group"] != "energy"
              and sum(1 for e in c["engines"] if e.get("final_state") and e.get("final")) >= 1]
    states = manifest.get("headlines", {}).get("cloth_states", {})
    return [comparison_page(c, states.get(f"{c['group']}/{c['scene']}")) for c in chosen]
