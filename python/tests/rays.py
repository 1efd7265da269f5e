"""Rays around a mesh, for the tests and python/bench/overhead.py (numpy only)."""

import numpy as np


def shell_rays(vertices, n, seed=0):
    """`n` rays (n, 6) from a sphere around `vertices` aimed near their centre (about half of
    them hit the bunny), each direction scaled by a random factor in [0.5, 2)."""
    rng = np.random.default_rng(seed)
    centre = (vertices.min(0) + vertices.max(0)) / 2
    radius = np.linalg.norm(vertices.max(0) - vertices.min(0))
    out = rng.normal(size=(n, 3))
    origin = centre + radius * out / np.linalg.norm(out, axis=1, keepdims=True)
    target = centre + 0.3 * radius * rng.uniform(-1, 1, size=(n, 3))
    direction = (target - origin) * rng.uniform(0.5, 2.0, size=(n, 1))
    return np.hstack([origin, direction])
