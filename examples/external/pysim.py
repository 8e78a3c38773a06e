#!/usr/bin/env python3
"""A mass-spring simulator in Python with numpy, run by springcheck as an external engine.

    pysim.py MODEL_JSON OUT_DIR

Reads the model file springcheck writes (docs/external-engines.md), steps it and writes what
springcheck reads back:

    OUT_DIR/times.npy       float64 (frames,): the frame times the model asks for
    OUT_DIR/trajectory.npy  float64 (frames, particles, 6): x y z vx vy vz per frame
    OUT_DIR/summary.json    its own stepping time, evaluations, and a blow-up if one happened

It steps by XPBD when the model's integrator is `xpbd` (its substeps and iterations), and by
symplectic Euler -- v += h a(t, x, v); x += h v -- for any other, both as the protocol page's
rules say ("Matching mysim's integrators to the last bit"): forces of gravity, drag, wind, damped
springs and hinges summed in mysim's order; pins on their path after the step; particles touching
a collider (sphere, plane, box) moved onto its surface grown by its margin, stripped of their
inward velocity, with its Coulomb friction. So it agrees with `mysim:symplectic-euler` and
`mysim:xpbd` at `tolerance` 0 to the bit (tests/protocol_rules_test.cpp). Copy it to start yours.
"""
import json
import math
import os
import sys
import time

import numpy as np


def dot3(a, b):
    """Row-wise a . b of (n, 3) arrays, summed x + y + z left to right (as mysim sums)."""
    return a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1] + a[:, 2] * b[:, 2]


def signed_distance(collider, x):
    """Distance of each point to a collider's surface, negative inside."""
    if collider["type"] == "sphere":
        d = x - np.array(collider["center"], dtype=float)
        return np.sqrt(dot3(d, d)) - collider["radius"]
    if collider["type"] == "plane":
        normal = np.array(collider["normal"], dtype=float)
        return dot3(np.tile(normal, (len(x), 1)), x - np.array(collider["point"], dtype=float))
    q = np.abs(x - np.array(collider["center"], dtype=float)) - np.array(collider["half_extents"], dtype=float)
    outside = np.maximum(q, 0.0)
    return np.sqrt(dot3(outside, outside)) + np.minimum(q.max(axis=1), 0.0)


def contact(collider, x, others, start):
    """Which particles touch a collider (closer than its margin, or inside), the point of its
    surface grown by the margin each must go to, and the outward normal there
    (docs/external-engines.md, "After every step"). `others`: the model's other colliders, whose
    inside a box's exit must avoid; `start`: where the particles were as the step began (a box's
    exit is the face a particle came in by)."""
    margin = collider["margin"]
    if collider["type"] == "sphere":
        centre = np.array(collider["center"], dtype=float)
        surface = collider["radius"] + margin
        d = x - centre
        r2 = dot3(d, d)
        r = np.sqrt(r2)
        normal = np.where(r[:, None] > 0, d / np.where(r > 0, r, 1.0)[:, None], np.array([0.0, 1.0, 0.0]))
        return r2 < surface * surface, centre + surface * normal, normal
    if collider["type"] == "plane":
        normal = np.array(collider["normal"], dtype=float)
        distance = signed_distance(collider, x)
        return distance < margin, x + (margin - distance)[:, None] * normal, np.tile(normal, (len(x), 1))
    if collider["type"] == "box":
        return box_contact(collider, x, others, start)
    sys.exit(f"pysim: collider type {collider['type']!r} not handled")


def entry_face(half, local, from_local):
    """The face a particle now at `local` (inside) came in by from `from_local`, as (axis, side):
    the slab its straight path entered last; None if it was inside already."""
    side = np.where(from_local < 0, -1.0, 1.0)
    outside = side * from_local - half
    entered = np.where(outside > 0, outside / np.where(outside > 0, side * (from_local - local), 1.0), -1.0)
    axis = int(np.argmax(entered))  # the first axis on a tie, as mysim's strict comparison
    return (axis, side[axis]) if entered[axis] > 0 else None


def box_contact(box, x, others, start):
    centre, half = (np.array(box[key], dtype=float) for key in ("center", "half_extents"))
    margin = box["margin"]
    local = x - centre
    q = np.abs(local) - half
    inside = q.max(axis=1) <= 0
    # Outside: along the line from the nearest box point, within the margin.
    nearest = centre + np.clip(local, -half, half)
    out = x - nearest
    d = np.sqrt(dot3(out, out))
    touching = inside | (d < margin)
    normal = out / np.where(d > 0, d, 1.0)[:, None]
    point = nearest + margin * normal
    # Inside: out through a face to margin beyond it, the way in first, then the nearest (on each
    # axis its own side first, the earlier axis on a tie), skipping exits into another collider.
    for p in np.nonzero(inside)[0]:
        entry = entry_face(half, local[p], start[p] - centre)
        exits = []
        for axis in range(3):
            near = -1.0 if local[p, axis] < 0 else 1.0
            for side in (near, -near):
                e = x[p].copy()
                e[axis] = centre[axis] + side * (half[axis] + margin)
                way_in = (axis, side) == entry
                exits.append((not way_in, half[axis] - side * local[p, axis], e, side * np.eye(3)[axis]))
        exits.sort(key=lambda item: item[:2])  # stable: ties keep the order above
        chosen = next((ex for ex in exits
                       if not any(signed_distance(o, ex[2][None, :])[0] < 0 for o in others)), exits[0])
        point[p], normal[p] = chosen[2], chosen[3]
    return touching, point, normal


def incidence_table(owners, count):
    """For items touching particles (owners[e] the particle of incidence e, incidences listed in
    item order), each particle's incidences in that order as the columns of a padded table:
    (count, width) indices into the incidence list, -1 where a particle has fewer."""
    order = np.argsort(owners, kind="stable")
    sorted_owners = owners[order]
    starts = np.searchsorted(sorted_owners, np.arange(count))
    rank = np.arange(len(order)) - starts[sorted_owners]
    width = int(rank.max()) + 1 if len(order) else 0
    table = np.full((count, width), -1, dtype=int)
    table[sorted_owners, rank] = order
    return table


class Model:
    """The model file's arrays, and mysim's force law on them (the protocol page's "State and
    forces", each operation as written there)."""

    def __init__(self, model, model_path):
        particles = model["particles"]
        self.n = int(particles["count"])
        self.start_x = np.array(particles["position"], dtype=float).reshape(-1, 3)
        self.start_v = np.array(particles["velocity"], dtype=float).reshape(-1, 3)
        self.mass = np.array(particles["mass"], dtype=float)
        self.inverse_mass = 1.0 / self.mass
        self.pinned = np.array(particles["pinned"], dtype=bool)
        self.free = ~self.pinned
        springs = model["springs"]
        self.i = np.array(springs["i"], dtype=int)
        self.j = np.array(springs["j"], dtype=int)
        self.rest = np.array(springs["rest_length"], dtype=float)
        self.k = np.array(springs["stiffness"], dtype=float)
        self.c = np.array(springs["damping"], dtype=float)
        self.damped = bool(np.any(self.c != 0.0))
        # Each particle's springs in spring index order (incidence 2s is spring s at its end i,
        # 2s + 1 at its end j), as mysim sums them.
        ends = np.empty(2 * len(self.i), dtype=int)
        ends[0::2], ends[1::2] = self.i, self.j
        others = np.empty_like(ends)
        others[0::2], others[1::2] = self.j, self.i
        table = incidence_table(ends, self.n)
        self.spring_columns = []  # per column: the particles that have one, its spring, the other end
        for col in range(table.shape[1]):
            rows = table[:, col] >= 0
            self.spring_columns.append((rows, table[rows, col] // 2, others[table[rows, col]]))
        # Hinge bending: b = sum_a w_a x_a per hinge (a flat rest state); each particle's hinges
        # in hinge index order.
        hinges = model.get("hinges", {"count": 0})
        self.hinge_count = int(hinges["count"])
        if self.hinge_count:
            self.hinge_particles = np.array(hinges["particles"], dtype=int).reshape(-1, 4)
            self.hinge_weights = np.array(hinges["weights"], dtype=float).reshape(-1, 4)
            self.hinge_stiffness = np.array(hinges["stiffness"], dtype=float)
            table = incidence_table(self.hinge_particles.reshape(-1), self.n)
            self.hinge_columns = [(table[:, col] >= 0, table[:, col][table[:, col] >= 0])
                                  for col in range(table.shape[1])]
        self.gravity = np.array(model["gravity"], dtype=float)
        self.drag = float(model["drag"])
        self.wind = model["wind"]
        if self.wind is not None:
            # Force on particle p in gust window floor(t / gust_period): table[window, p] * direction.
            self.wind_table = np.load(os.path.join(os.path.dirname(model_path), self.wind["force_table"]))
            self.wind_direction = np.array(self.wind["direction"], dtype=float)
        self.pins = model["pin_motion"]
        self.colliders = model["colliders"]
        # Where each particle was when the step began: friction undoes or shortens the slide
        # since then (the protocol page's "Friction").
        self.step_start = self.start_x.copy()

    def hinge_vectors(self, x):
        """b = w_0 x_0, then b + w_a x_a for a = 1, 2, 3: (H, 3)."""
        b = self.hinge_weights[:, 0, None] * x[self.hinge_particles[:, 0]]
        for a in range(1, 4):
            b = b + self.hinge_weights[:, a, None] * x[self.hinge_particles[:, a]]
        return b

    def external_force(self, t, v):
        f = self.mass[:, None] * self.gravity - self.drag * v
        if self.wind is not None:
            window = int(math.floor(t / self.wind["gust_period"]))
            f = f + self.wind_table[window][:, None] * self.wind_direction
        return f

    def force(self, t, x, v):
        """Every particle's force: external, then springs in index order, then hinges."""
        d = x[self.j] - x[self.i]
        inverse_length = 1.0 / np.sqrt(dot3(d, d))
        scale = self.k * (1.0 - self.rest * inverse_length)
        if self.damped:
            scale = scale + self.c * dot3(d, v[self.j] - v[self.i]) * inverse_length * inverse_length
        f = self.external_force(t, v)
        for rows, spring, other in self.spring_columns:
            f[rows] = f[rows] + scale[spring][:, None] * (x[other] - x[rows])
        if self.hinge_count:
            kb = self.hinge_stiffness[:, None] * self.hinge_vectors(x)
            weights = self.hinge_weights.reshape(-1)
            for rows, incidences in self.hinge_columns:
                f[rows] = f[rows] - weights[incidences][:, None] * kb[incidences // 4]
        return f

    def pin_path(self, t):
        """The pinned particles' positions and velocity at t."""
        if self.pins is None:
            return self.start_x[self.pinned], 0.0
        w = 2.0 * math.pi * self.pins["frequency"]
        axis = np.array(self.pins["axis"], dtype=float)
        offset = self.pins["amplitude"] * math.sin(w * t) * axis
        return self.start_x[self.pinned] + offset, self.pins["amplitude"] * w * math.cos(w * t) * axis

    def after_step(self, t, x, v):
        """Pins on their path, then every collider's contacts in the model's order."""
        x[self.pinned], v[self.pinned] = self.pin_path(t)
        for index, collider in enumerate(self.colliders):
            others = self.colliders[:index] + self.colliders[index + 1:]
            touching, point, normal = contact(collider, x, others, self.step_start)
            touching &= self.free
            if np.any(touching):
                rows = np.nonzero(touching)[0]
                n = normal[rows]
                pushed = np.maximum(0.0, dot3(point[rows] - x[rows], n))
                x[rows] = point[rows]
                vn = dot3(v[rows], n)
                inward = vn < 0.0
                v[rows[inward]] = v[rows[inward]] - vn[inward][:, None] * n[inward]
                if "friction" in collider:
                    apply_friction(collider["friction"], rows, n, pushed, np.maximum(0.0, -vn),
                                   self.step_start, x, v)
        self.step_start = x.copy()


def tangential(u, n):
    return u - dot3(u, n)[:, None] * n


def apply_friction(friction, rows, n, pushed, stopped, start, x, v):
    """Coulomb's law on the contact projection (the protocol page's "Friction"): the slide since
    the step began is undone when static friction can stop it and the tangential velocity (mu_s
    times what the normal projection pushed and stopped), else both shortened by mu_k times it."""
    mu_s, mu_k = friction["static"], friction["kinetic"]
    slid = tangential(x[rows] - start[rows], n)
    vt = tangential(v[rows], n)
    slid_length = np.sqrt(dot3(slid, slid))
    speed = np.sqrt(dot3(vt, vt))
    stick = (slid_length <= mu_s * pushed) & (speed <= mu_s * stopped)
    with np.errstate(divide="ignore", invalid="ignore"):
        keep_x = np.where(stick, 1.0, np.minimum(1.0, np.where(slid_length > 0, mu_k * pushed / slid_length, 0.0)))
        keep_v = np.where(stick, 1.0, np.minimum(1.0, np.where(speed > 0, mu_k * stopped / speed, 0.0)))
    x[rows] = x[rows] - slid * keep_x[:, None]
    v[rows] = v[rows] - vt * keep_v[:, None]


def symplectic_euler_step(model, t, x, v, h):
    a = model.force(t, x, v) * model.inverse_mass[:, None]
    free = model.free
    v[free] = v[free] + h * a[free]
    x[free] = x[free] + h * v[free]
    t += h  # summed as springcheck sums it, so frame times match exactly
    model.after_step(t, x, v)
    return t, 1


class Xpbd:
    """XPBD with substeps (Macklin et al. 2016, 2019) as the protocol page's `xpbd` row: springs
    as compliant distance constraints colour by colour, then hinges as vector constraints in index
    order, `iterations` passes a substep."""

    def __init__(self, model, settings):
        self.substeps = int(settings["substeps"])
        self.iterations = int(settings["iterations"])
        self.w = np.where(model.pinned, 0.0, model.inverse_mass)
        # Greedy colours in spring index order: the smallest colour no earlier spring at either
        # end has. A colour's springs share no particle, so one colour is one array operation.
        used = [set() for _ in range(model.n)]
        colours = []
        for s, (i, j) in enumerate(zip(model.i, model.j)):
            c = 0
            while c in used[i] or c in used[j]:
                c += 1
            if c == len(colours):
                colours.append([])
            colours[c].append(s)
            used[i].add(c)
            used[j].add(c)
        self.colours = [np.array(c, dtype=int) for c in colours]

    def step(self, model, t, x, v, h):
        hs = h / self.substeps
        alpha = 1.0 / (model.k * hs * hs)
        gamma = model.c / (model.k * hs)
        free = model.free
        for _ in range(self.substeps):
            f = model.external_force(t, v)
            v[free] = v[free] + (hs * model.inverse_mass[free])[:, None] * f[free]
            x_prev = x.copy()
            t += hs
            x[free] = x[free] + hs * v[free]
            x[model.pinned] = model.pin_path(t)[0]
            lam = np.zeros(len(model.i))
            hinge_lam = np.zeros((model.hinge_count, 3))
            for _ in range(self.iterations):
                for colour in self.colours:
                    self.project_springs(model, colour, x, x_prev, lam, alpha, gamma)
                if model.hinge_count:
                    self.project_hinges(model, x, hinge_lam, hs)
            v[:] = (x - x_prev) / hs
            model.after_step(t, x, v)
        return t, self.substeps

    def project_springs(self, model, colour, x, x_prev, lam, alpha, gamma):
        i, j = model.i[colour], model.j[colour]
        wi, wj = self.w[i], self.w[j]
        d = x[i] - x[j]
        length = np.sqrt(dot3(d, d))
        act = (wi + wj != 0.0) & (length != 0.0)
        if not np.all(act):
            colour, i, j, wi, wj, d, length = (a[act] for a in (colour, i, j, wi, wj, d, length))
        unit = d / length[:, None]
        moved = (x[i] - x_prev[i]) - (x[j] - x_prev[j])
        a, g = alpha[colour], gamma[colour]
        dlam = (-(length - model.rest[colour]) - a * lam[colour] - g * dot3(unit, moved)) / \
            ((1.0 + g) * (wi + wj) + a)
        x[i] = x[i] + (wi * dlam)[:, None] * unit
        x[j] = x[j] - (wj * dlam)[:, None] * unit
        lam[colour] = lam[colour] + dlam

    def project_hinges(self, model, x, hinge_lam, hs):
        # One after another: neighbouring hinges share particles (Gauss-Seidel, as mysim).
        w = self.w
        for k in range(model.hinge_count):
            p = model.hinge_particles[k]
            weights = model.hinge_weights[k]
            alpha = 1.0 / (model.hinge_stiffness[k] * hs * hs)
            denominator = alpha
            for a in range(4):
                denominator = denominator + weights[a] * weights[a] * w[p[a]]
            if denominator == alpha:
                continue  # all four pinned
            b = weights[0] * x[p[0]]
            for a in range(1, 4):
                b = b + weights[a] * x[p[a]]
            dlam = (-b - alpha * hinge_lam[k]) / denominator
            for a in range(4):
                x[p[a]] = x[p[a]] + (weights[a] * w[p[a]]) * dlam
            hinge_lam[k] = hinge_lam[k] + dlam


def main(model_path, out_dir):
    with open(model_path) as f:
        description = json.load(f)
    model = Model(description, model_path)
    x, v = model.start_x.copy(), model.start_v.copy()
    settings = description["integrator"]
    if settings["name"] == "xpbd":
        step = Xpbd(model, settings).step
    else:
        step = symplectic_euler_step

    dt = float(description["dt"])
    steps = int(description["steps"])
    frame_steps = description["frame_steps"]
    times, frames = [0.0], [np.hstack([x, v])]
    blowup = None
    t = 0.0
    evaluations = 0
    began = time.perf_counter()
    for n in range(1, steps + 1):
        t, used = step(model, t, x, v, dt)
        evaluations += used
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
            blowup = {"time": t, "reason": "a position or velocity became non-finite"}
            break
        if len(times) < len(frame_steps) and frame_steps[len(times)] == n:
            times.append(t)
            frames.append(np.hstack([x, v]))
    elapsed = time.perf_counter() - began

    os.makedirs(out_dir, exist_ok=True)
    np.save(os.path.join(out_dir, "times.npy"), np.array(times))
    np.save(os.path.join(out_dir, "trajectory.npy"), np.array(frames).reshape(len(frames), model.n, 6))
    with open(os.path.join(out_dir, "summary.json"), "w") as f:
        json.dump({"wall_seconds": elapsed, "derivative_evaluations": evaluations, "blowup": blowup}, f)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: pysim.py MODEL_JSON OUT_DIR")
    main(sys.argv[1], sys.argv[2])
