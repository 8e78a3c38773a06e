#!/usr/bin/env python3
"""A mass-spring simulator in Python with numpy, run by springcheck as an external engine.

    pysim.py MODEL_JSON OUT_DIR

Reads the model file springcheck writes (docs/external-engines.md), steps it with symplectic
Euler -- v += h a(t, x, v); x += h v -- and writes what springcheck reads back:

    OUT_DIR/times.npy       float64 (frames,): the frame times the model asks for
    OUT_DIR/trajectory.npy  float64 (frames, particles, 6): x y z vx vy vz per frame
    OUT_DIR/summary.json    its own stepping time, evaluations, and a blow-up if one happened

It does what springcheck's own symplectic Euler does, in the same order, so the two agree to
round-off: forces of gravity, drag, wind and damped springs; pinned particles put on their
prescribed path after the step; particles touching a collider (sphere, plane, box) moved onto
its surface grown by its margin and stripped of their inward velocity. Copy it as the start of your own engine.
"""
import json
import math
import os
import sys
import time

import numpy as np


def signed_distance(collider, x):
    """Distance of each point to a collider's surface, negative inside."""
    if collider["type"] == "sphere":
        d = x - np.array(collider["center"], dtype=float)
        return np.sqrt(np.einsum("ij,ij->i", d, d)) - collider["radius"]
    if collider["type"] == "plane":
        return (x - np.array(collider["point"], dtype=float)) @ np.array(collider["normal"], dtype=float)
    q = np.abs(x - np.array(collider["center"], dtype=float)) - np.array(collider["half_extents"], dtype=float)
    return np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)


def contact(collider, x, others):
    """Which particles touch a collider (closer than its margin, or inside), the point of its
    surface grown by the margin each must go to, and the outward normal there
    (docs/external-engines.md, "Colliders"). `others`: the model's other colliders, whose
    inside a box's exit must avoid."""
    margin = collider["margin"]
    if collider["type"] == "sphere":
        centre = np.array(collider["center"], dtype=float)
        surface = collider["radius"] + margin
        d = x - centre
        r = np.sqrt(np.einsum("ij,ij->i", d, d))
        normal = np.where(r[:, None] > 0, d / np.maximum(r[:, None], 1e-300), np.array([0.0, 1.0, 0.0]))
        return r < surface, centre + surface * normal, normal
    if collider["type"] == "plane":
        normal = np.array(collider["normal"], dtype=float)
        distance = (x - np.array(collider["point"], dtype=float)) @ normal
        return distance < margin, x + (margin - distance)[:, None] * normal, np.tile(normal, (len(x), 1))
    if collider["type"] == "box":
        return box_contact(collider, x, others)
    sys.exit(f"pysim: collider type {collider['type']!r} not handled")


def box_contact(box, x, others):
    centre = np.array(box["center"], dtype=float)
    half = np.array(box["half_extents"], dtype=float)
    margin = box["margin"]
    local = x - centre
    q = np.abs(local) - half
    inside = q.max(axis=1) <= 0
    # Outside: along the line from the nearest box point, within the margin.
    nearest = centre + np.clip(local, -half, half)
    out = x - nearest
    d = np.sqrt(np.einsum("ij,ij->i", out, out))
    touching = inside | (d < margin)
    normal = out / np.maximum(d, 1e-300)[:, None]
    point = nearest + margin * normal
    # Inside: out through a face to margin beyond it, the nearest face first (on each axis the
    # side the particle is on first, the earlier axis on a tie), skipping exits inside another
    # collider.
    rows = np.nonzero(inside)[0]
    for p in rows:
        exits = []
        for axis in range(3):
            near = -1.0 if local[p, axis] < 0 else 1.0
            for side in (near, -near):
                e = x[p].copy()
                e[axis] = centre[axis] + side * (half[axis] + margin)
                n = np.zeros(3)
                n[axis] = side
                exits.append((half[axis] - side * local[p, axis], e, n))
        exits.sort(key=lambda item: item[0])  # stable: ties keep the order above
        chosen = next((ex for ex in exits
                       if not any(signed_distance(o, ex[1][None, :])[0] < 0 for o in others)), exits[0])
        point[p], normal[p] = chosen[1], chosen[2]
    return touching, point, normal


def main(model_path, out_dir):
    with open(model_path) as f:
        model = json.load(f)
    particles = model["particles"]
    x = np.array(particles["position"], dtype=float).reshape(-1, 3)
    v = np.array(particles["velocity"], dtype=float).reshape(-1, 3)
    mass = np.array(particles["mass"], dtype=float)
    pinned = np.array(particles["pinned"], dtype=bool)
    free = ~pinned
    start = x.copy()
    n = len(mass)

    springs = model["springs"]
    i = np.array(springs["i"], dtype=int)
    j = np.array(springs["j"], dtype=int)
    rest = np.array(springs["rest_length"], dtype=float)
    k = np.array(springs["stiffness"], dtype=float)
    c = np.array(springs["damping"], dtype=float)
    damped = bool(np.any(c != 0.0))

    # Hinge bending: b = sum_a w_a x_a per hinge, F_a = -k w_a b (a flat rest state).
    hinges = model.get("hinges", {"count": 0})
    hinge_count = int(hinges["count"])
    if hinge_count:
        hinge_particles = np.array(hinges["particles"], dtype=int)  # (H, 4)
        hinge_weights = np.array(hinges["weights"], dtype=float)    # (H, 4)
        hinge_stiffness = np.array(hinges["stiffness"], dtype=float)

    gravity = np.array(model["gravity"], dtype=float)
    drag = float(model["drag"])
    wind = model["wind"]
    if wind is not None:
        # Force on particle p in gust window floor(t / gust_period): table[window, p] * direction.
        wind_table = np.load(os.path.join(os.path.dirname(model_path), wind["force_table"]))
        wind_direction = np.array(wind["direction"], dtype=float)
    pins = model["pin_motion"]
    colliders = model["colliders"]

    def pin_offset(t):
        w = 2.0 * math.pi * pins["frequency"]
        axis = np.array(pins["axis"], dtype=float)
        return (pins["amplitude"] * math.sin(w * t) * axis,
                pins["amplitude"] * w * math.cos(w * t) * axis)

    def acceleration(t, x, v):
        f = mass[:, None] * gravity - drag * v
        if wind is not None:
            window = int(math.floor(t / wind["gust_period"]))
            f += wind_table[window][:, None] * wind_direction
        d = x[j] - x[i]
        length = np.sqrt(np.einsum("ij,ij->i", d, d))
        # F on i = [k (1 - rest / l) + c (d . w) / l^2] d, w = v_j - v_i; j feels the opposite.
        scale = k * (1.0 - rest / length)
        if damped:
            w = v[j] - v[i]
            scale = scale + c * np.einsum("ij,ij->i", d, w) / (length * length)
        spring = scale[:, None] * d
        np.add.at(f, i, spring)
        np.add.at(f, j, -spring)
        if hinge_count:
            b = np.einsum("ha,hac->hc", hinge_weights, x[hinge_particles])
            kb = hinge_stiffness[:, None] * b
            for a in range(4):
                np.add.at(f, hinge_particles[:, a], -hinge_weights[:, a, None] * kb)
        return f / mass[:, None]

    dt = float(model["dt"])
    steps = int(model["steps"])
    frame_steps = model["frame_steps"]
    times, frames = [], []
    wanted = 0

    def record(t):
        nonlocal wanted
        times.append(t)
        frames.append(np.hstack([x, v]))
        wanted += 1

    record(0.0)
    blowup = None
    t = 0.0
    began = time.perf_counter()
    for step in range(1, steps + 1):
        a = acceleration(t, x, v)
        v[free] += dt * a[free]
        x[free] += dt * v[free]
        t += dt  # summed as springcheck sums it, so frame times match exactly
        offset, velocity = pin_offset(t) if pins is not None else (0.0, 0.0)
        x[pinned] = start[pinned] + offset
        v[pinned] = velocity
        for index, collider in enumerate(colliders):  # in the model's order, as springcheck's engines
            touching, point, normal = contact(collider, x, colliders[:index] + colliders[index + 1:])
            touching &= free
            if np.any(touching):
                x[touching] = point[touching]
                vn = np.einsum("ij,ij->i", v[touching], normal[touching])
                v[touching] -= np.minimum(vn, 0.0)[:, None] * normal[touching]
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
            blowup = {"time": t, "reason": "a position or velocity became non-finite"}
            break
        if wanted < len(frame_steps) and frame_steps[wanted] == step:
            record(t)
    elapsed = time.perf_counter() - began

    os.makedirs(out_dir, exist_ok=True)
    np.save(os.path.join(out_dir, "times.npy"), np.array(times))
    np.save(os.path.join(out_dir, "trajectory.npy"), np.array(frames).reshape(len(frames), n, 6))
    with open(os.path.join(out_dir, "summary.json"), "w") as f:
        json.dump({"wall_seconds": elapsed, "derivative_evaluations": step if steps else 0,
                   "blowup": blowup}, f)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: pysim.py MODEL_JSON OUT_DIR")
    main(sys.argv[1], sys.argv[2])
