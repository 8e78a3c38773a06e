#!/usr/bin/env python3
"""A stand-in for a single-precision engine, for the precision-declaration tests: the example
engine's symplectic Euler, its positions and velocities then rounded to float32 as such an
engine would hand them over.

    float32_engine.py MODEL_JSON OUT_DIR
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "examples", "external"))
import pysim  # noqa: E402

pysim.main(sys.argv[1], sys.argv[2])
path = os.path.join(sys.argv[2], "trajectory.npy")
np.save(path, np.load(path).astype(np.float32).astype(np.float64))
