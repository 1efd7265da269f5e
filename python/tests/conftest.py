"""Shared fixtures: the mesh, the command-line programs the module is checked against, rays."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import wedge
from rays import shell_rays

REPO = pathlib.Path(__file__).resolve().parents[2]
MESHES = REPO.parent / "shared" / "meshes"
BUNNY = MESHES / "stanford-bunny.obj"


def program(name):
    """The `raycast` or `raytrace` binary: $WEDGE_RAYCAST / $WEDGE_RAYTRACE (set by .ci/run),
    else the test profile's build in target/debug. A missing one fails the test, never skips it."""
    path = os.environ.get(f"WEDGE_{name.upper()}") or str(REPO / "target" / "debug" / name)
    if not os.access(path, os.X_OK):
        pytest.fail(f"{path}: no {name} binary (build it: cargo build -p raytrace)")
    return path


def run(name, *args, ok=True):
    """Runs a program; returns the completed process (checking its exit status when `ok`)."""
    done = subprocess.run([program(name), *map(str, args)], capture_output=True, text=True)
    if ok and done.returncode != 0:
        pytest.fail(f"{name} {' '.join(map(str, args))}: {done.stderr.strip()}")
    return done


@pytest.fixture(scope="session")
def bunny_path():
    if not BUNNY.is_file():
        pytest.fail(f"{BUNNY}: the test meshes are missing (see README.md)")
    return BUNNY


@pytest.fixture(scope="session")
def bunny(bunny_path):
    return wedge.Scene.from_file(bunny_path)


def bunny_rays(scene, n, seed=1, segments=False):
    """`n` rays from a sphere around `scene` aimed near its centre (about half hit), with a
    few misses by definition (NaN, infinite, zero direction); (n, 8) with t_min, t_max."""
    rays = shell_rays(scene.vertices, n, seed)
    rng = np.random.default_rng(seed + 1000)
    if segments:
        t_min = rng.uniform(0.0, 0.6, size=(n, 1))
        t_max = t_min + rng.uniform(0.0, 1.0, size=(n, 1))
        rays = np.hstack([rays, t_min, t_max])
        rays[7, 6] = np.nan
    rays[0, 0] = np.nan
    rays[1, 4] = np.inf
    rays[2, 3:6] = 0.0
    return rays
