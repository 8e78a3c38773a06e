#!/usr/bin/env python3
"""An external engine that misbehaves on purpose, one way per MODE, for the refusal tests.

    misbehaving_engine.py MODE MODEL_JSON OUT_DIR

It runs no physics: every particle stays where it starts, which is a valid answer only in the
"well" and "blowup" modes' frames.
"""
import json
import os
import sys
import time

import numpy as np

mode, model_path, out = sys.argv[1], sys.argv[2], sys.argv[3]
with open(model_path) as f:
    model = json.load(f)
n = model["particles"]["count"]
times = np.array(model["frame_times"], dtype=float)
state = np.hstack([np.array(model["particles"]["position"], dtype=float).reshape(-1, 3),
                   np.zeros((n, 3))])
frames = np.repeat(state[None, :, :], len(times), axis=0)
summary = {"wall_seconds": 0.001}

if mode == "exit-code":
    print("something went wrong inside the engine", file=sys.stderr)
    sys.exit(3)
if mode == "timeout":
    time.sleep(60)
if mode == "wrong-shape":
    frames = frames[:, :, :3]
if mode == "particle-count":
    frames = frames[:, :-1, :]
if mode == "nan":
    frames[len(times) // 2, 0, 1] = np.nan
if mode == "short":
    times, frames = times[: len(times) // 2], frames[: len(times) // 2]
if mode == "wrong-times":
    times = times * 1.5
if mode == "blowup":  # stops half way, declaring a time between two frames
    times, frames = times[: len(times) // 2], frames[: len(times) // 2]
    summary["blowup"] = {"time": float(times[-1]) + 0.003, "reason": "the test engine gave up"}
if mode == "blowup-nonfinite-last":  # stops half way on the frame that went non-finite
    times, frames = times[: len(times) // 2], frames[: len(times) // 2]
    frames[-1, 0, 0] = np.inf
    summary["blowup"] = {"time": float(times[-1]), "reason": "position overflowed"}
if mode == "negative-evaluations":
    summary["derivative_evaluations"] = -5
if mode == "huge-evaluations":
    summary["derivative_evaluations"] = 2**64 - 1
if mode == "blowup-every-frame":  # declares a blow-up but returns the whole run
    summary["blowup"] = {"time": float(times[len(times) // 2]), "reason": "?"}
if mode == "blowup-before-start":
    times, frames = times[: len(times) // 2], frames[: len(times) // 2]
    summary["blowup"] = {"time": -5.0, "reason": "?"}
if mode == "no-evaluations":  # a summary without the optional counts
    summary = {}
np.save(os.path.join(out, "times.npy"), times)
if mode != "missing-file":
    np.save(os.path.join(out, "trajectory.npy"), frames)
with open(os.path.join(out, "summary.json"), "w") as f:
    json.dump(summary, f)
