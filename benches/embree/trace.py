"""Embree 4 on the rays of `cargo bench --bench interleaved` (or `versus`): the reference row.

Run by the benches (never by hand, though it can be) as

    python3 trace.py DIR MESH.tri RAYS:QUERY [RAYS:QUERY ...]

where DIR holds what the bench wrote: MESH.tri (n x 3 x 3 little-endian f32, each
triangle's vertices) and `RAYS.ray` for each RAYS named (n x 6 f32: origin, then
direction), and QUERY is `closest` or `any`. Prints one line: for each set the best Mrays/s
of three traces, then for each set the binding's own cost per ray in ns (the same rays and
query on an empty scene, where Embree returns at once), which the benches subtract for their
`embree4-net` rows.

Measured warm: each set is cast once, untimed, before the three timed traces (in a fresh
process Embree's first casts run about 2x slower; the best of three alone would hide that
only when the first trace is not the best).

Uses the `embreex` package (pip install embreex): Embree 4 behind a Cython loop that makes
one `rtcIntersect1` or `rtcOccluded1` call per ray, on one thread, with t in [0, 1e37].
The project does not depend on it: without it the bench leaves the Embree rows out.
"""

import sys
import time

import numpy as np
from embreex import rtcore_scene
from embreex.mesh_construction import TriangleMesh

REPEATS = 3
QUERIES = {"closest": "INTERSECT", "any": "OCCLUDED"}


def best_mrays(scene, origins, dirs, query):
    scene.run(origins, dirs, query=query)  # the warm-up cast, discarded
    best = 0.0
    for _ in range(REPEATS):
        start = time.perf_counter()
        scene.run(origins, dirs, query=query)
        best = max(best, len(origins) / (time.perf_counter() - start) / 1e6)
    return best


def main():
    folder, mesh, specs = sys.argv[1], sys.argv[2], sys.argv[3:]
    triangles = np.fromfile(f"{folder}/{mesh}", dtype="<f4").reshape(-1, 3, 3)
    scene = rtcore_scene.EmbreeScene()
    TriangleMesh(scene, triangles)
    empty = rtcore_scene.EmbreeScene()
    figures, overheads_ns, loaded = [], [], {}
    for spec in specs:
        name, query = spec.split(":")
        if name not in loaded:
            rays = np.fromfile(f"{folder}/{name}.ray", dtype="<f4").reshape(-1, 6)
            loaded[name] = np.ascontiguousarray(rays[:, :3]), np.ascontiguousarray(rays[:, 3:])
        origins, dirs = loaded[name]
        figures.append(best_mrays(scene, origins, dirs, QUERIES[query]))
        overheads_ns.append(1e3 / best_mrays(empty, origins, dirs, QUERIES[query]))
    print(" ".join(str(x) for x in figures + overheads_ns))


if __name__ == "__main__":
    main()
