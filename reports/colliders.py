"""The static colliders of a scene (the manifest's model.colliders), drawn in true proportions from
the quads of their surface that springcheck writes (model.colliders[i].surface: a sphere's
parallels and meridians, a box's faces, a square of a plane under the cloth's start): 3D wire
frames for the drape's mesh view and outlines for its flat views. The report names no shape.
Drawing only."""
import numpy as np
from matplotlib.patches import Polygon
from mpl_toolkits.mplot3d.art3d import Line3DCollection


def _surface(c):
    """(points N x 3, quads M x 4) of a collider, or None when the comparison predates them."""
    s = c.get("surface")
    if not s or not s.get("quads"):
        return None
    return np.asarray(s["points"], float), np.asarray(s["quads"], int)


def _edges(quads):
    """Each quad side once (a closed surface shares every side between two quads)."""
    sides = np.concatenate([quads[:, [k, (k + 1) % 4]] for k in range(4)])
    sides = np.unique(np.sort(sides, axis=1), axis=0)
    return sides[sides[:, 0] != sides[:, 1]]


def draw_3d(ax, colliders, cloth):
    """Wire frames on a 3D axis whose axes are (x, z, y), as the drape pages draw; returns the
    points drawn, so the caller can frame them with the cloth."""
    drawn = [np.empty((0, 3))]
    for c in colliders:
        surface = _surface(c)
        if surface is None:
            continue
        points, quads = surface
        lines = points[_edges(quads)][:, :, [0, 2, 1]]
        ax.add_collection3d(Line3DCollection(lines, colors="0.5", linewidths=0.4, alpha=0.6))
        drawn.append(points)
    return np.vstack(drawn)


def _turn(o, a, b):
    """The z of (a - o) x (b - o): positive when o, a, b turn counter-clockwise."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _hull(points):
    """The convex hull of 2D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(map(tuple, np.round(points, 12))))
    if len(pts) < 3:
        return np.asarray(pts)

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and _turn(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]

    return np.asarray(half(pts) + half(pts[::-1]))


def draw_flat(ax, colliders, u, v):
    """Outlines in the flat view across axes u and v (0 x, 1 y, 2 z): each surface's silhouette,
    the hull of its points seen along the third axis (every shape springcheck has is convex)."""
    for c in colliders:
        surface = _surface(c)
        if surface is None:
            continue
        hull = _hull(surface[0][:, [u, v]])
        if len(hull) >= 2:
            ax.add_patch(Polygon(hull, closed=True, fill=False, color="0.5", lw=0.8, linestyle="--"))
