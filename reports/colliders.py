"""The static colliders of a scene (the manifest's model.colliders), drawn in true proportions:
3D wire frames for the drape's mesh view and outlines for its flat views. Drawing only."""
import math

import numpy as np
from matplotlib.patches import Circle, Rectangle


def _sphere_wire(c, n=24):
    u, v = np.meshgrid(np.linspace(0, 2 * math.pi, n), np.linspace(0, math.pi, n // 2))
    x, r = c["center"], c["radius"]
    return x[0] + r * np.cos(u) * np.sin(v), x[1] + r * np.cos(v), x[2] + r * np.sin(u) * np.sin(v)


def _plane_patch(c, cloth):
    """A square of the plane under the cloth, as wide as the cloth spreads (at least 0.5 m)."""
    n = np.asarray(c["normal"], float)
    p = np.asarray(c["point"], float)
    middle = 0.5 * (cloth.min(axis=0) + cloth.max(axis=0))
    foot = middle - n.dot(middle - p) * n
    half = max(0.25, 0.6 * float(np.linalg.norm(cloth.max(axis=0) - cloth.min(axis=0))))
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    w = np.cross(n, u)
    s = np.linspace(-half, half, 5)
    a, b = np.meshgrid(s, s)
    pts = foot[None, None, :] + a[..., None] * u + b[..., None] * w
    return pts[..., 0], pts[..., 1], pts[..., 2]


def _box_wire(c):
    lo = np.asarray(c["center"], float) - np.asarray(c["half_extents"], float)
    hi = np.asarray(c["center"], float) + np.asarray(c["half_extents"], float)
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    edges = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]
    return corners, edges


def draw_3d(ax, colliders, cloth):
    """Wire frames on a 3D axis whose axes are (x, z, y), as the drape pages draw; returns the
    points drawn, so the caller can frame them with the cloth."""
    drawn = [np.empty((0, 3))]
    for c in colliders:
        if c["type"] == "sphere":
            sx, sy, sz = _sphere_wire(c)
        elif c["type"] == "plane":
            sx, sy, sz = _plane_patch(c, cloth)
        elif c["type"] == "box":
            corners, edges = _box_wire(c)
            for a, b in edges:
                ax.plot(*corners[[a, b]][:, [0, 2, 1]].T, color="0.5", lw=0.6, alpha=0.7)
            drawn.append(corners)
            continue
        else:
            continue
        ax.plot_wireframe(sx, sz, sy, color="0.5", lw=0.4, alpha=0.6)
        drawn.append(np.column_stack([sx.ravel(), sy.ravel(), sz.ravel()]))
    return np.vstack(drawn)


def draw_flat(ax, colliders, u, v):
    """Outlines in the flat view across axes u and v (0 x, 1 y, 2 z)."""
    style = dict(fill=False, color="0.5", lw=0.8, linestyle="--")
    for c in colliders:
        if c["type"] == "sphere":
            ax.add_patch(Circle((c["center"][u], c["center"][v]), c["radius"], **style))
        elif c["type"] == "box":
            lo = [c["center"][k] - c["half_extents"][k] for k in (u, v)]
            ax.add_patch(Rectangle(lo, 2 * c["half_extents"][u], 2 * c["half_extents"][v], **style))
        elif c["type"] == "plane":
            n = c["normal"]
            if abs(n[u]) + abs(n[v]) > 0.99:  # seen edge on: its trace is a line
                ax.axline((c["point"][u], c["point"][v]), slope=-n[u] / n[v] if n[v] else math.inf,
                          color="0.5", lw=0.8, linestyle="--")
