"""Per-call cost of tracing 1, 1k and 1M rays through the bunny: the wedge module (scene built
once), a `raycast` process per call (process start, mesh load, BVH build, trace, write), and
embreex (Embree through Python, scene built once) when it is installed.

    python python/bench/overhead.py [--raycast target/release/raycast] [--reps 5]

Prints a markdown table of median wall times per call (closest hit, float32 rays, the `la`
back end). Run from the repository's root; the bunny is ../shared/meshes/stanford-bunny.obj.
"""

import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import wedge

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
from rays import shell_rays  # noqa: E402  (the tests' rays, from python/tests/rays.py)

BUNNY = pathlib.Path("../shared/meshes/stanford-bunny.obj")


def rays_for(scene, n):
    return shell_rays(scene.vertices, n).astype(np.float32)


def median_time(call, reps):
    times = []
    for _ in range(reps):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def fmt(seconds):
    return f"{seconds * 1e3:.3f} ms" if seconds < 1 else f"{seconds:.2f} s"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--raycast", default="target/release/raycast")
    parser.add_argument("--reps", type=int, default=5)
    args = parser.parse_args()

    start = time.perf_counter()
    scene = wedge.Scene.from_file(BUNNY)
    build = time.perf_counter() - start
    try:
        import embreex.rtcore_scene as rtcs
        from embreex.mesh_construction import TriangleMesh

        start = time.perf_counter()
        embree = rtcs.EmbreeScene()
        TriangleMesh(embree, scene.vertices.astype(np.float32), scene.faces.astype(np.int32))
        embree_build = time.perf_counter() - start
    except ImportError:
        embree = None

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (1, 1000, 1_000_000):
            rays = rays_for(scene, n)
            wedge_t = median_time(lambda: scene.cast_rays(rays), args.reps)
            path = os.path.join(tmp, "rays.npy")
            np.save(path, rays)
            cmd = [args.raycast, str(BUNNY), path, os.path.join(tmp, "hits.npy"), "--quiet"]
            raycast_t = median_time(lambda: subprocess.run(cmd, check=True), args.reps)
            if embree is not None:
                o = np.ascontiguousarray(rays[:, :3])
                d = np.ascontiguousarray(rays[:, 3:])
                embree_t = fmt(median_time(lambda: embree.run(o, d, output=1), args.reps))
            else:
                embree_t = "not installed"
            rows.append((n, fmt(wedge_t), fmt(raycast_t), embree_t))

    print(f"bunny ({len(scene)} triangles), closest hit, float32 rays, median of {args.reps}")
    print(f"wedge.Scene.from_file (load + BVH, once): {fmt(build)}", end="")
    print(f"; embreex scene (once): {fmt(embree_build)}" if embree is not None else "")
    print()
    print("| rays | wedge `cast_rays` | `raycast` process | embreex `run(output=1)` |")
    print("| ---: | ---: | ---: | ---: |")
    for n, w, r, e in rows:
        print(f"| {n:,} | {w} | {r} | {e} |")


if __name__ == "__main__":
    main()
