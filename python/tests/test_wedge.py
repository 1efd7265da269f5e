"""The wedge module against the command-line programs, bit for bit, and its error handling."""

import re
import threading
import time

import numpy as np
import pytest

import wedge
from conftest import REPO, bunny_rays, run

ALL = [b["name"] for b in wedge.backends()]


def same_bits(a, b):
    """Equal arrays, NaN for NaN, -0.0 distinct from 0.0."""
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    assert a.shape == b.shape and a.dtype == b.dtype, (a.shape, a.dtype, b.shape, b.dtype)
    return np.array_equal(a.view(np.uint8), b.view(np.uint8))


def raycast_hits(tmp_path, mesh, rays, *options):
    path = tmp_path / "rays.npy"
    np.save(path, rays)
    out = tmp_path / "hits.npy"
    run("raycast", mesh, path, out, "--quiet", *options)
    return np.load(out)


def test_backends_are_the_registry():
    listed = wedge.backends()
    assert [b["name"] for b in listed][0] == "la"
    assert len({b["name"] for b in listed}) == len(listed) >= 20
    help_text = run("raycast", "--help").stdout
    for b in listed:
        assert b["name"] in help_text
        assert b["algebra"] in {"la", "g3", "pga", "cga"}
        assert isinstance(b["watertight"], bool) and isinstance(b["exact"], bool)
        assert b["method"] and b["help"]


@pytest.mark.parametrize("backend", ALL)
def test_cast_rays_is_raycast_bit_for_bit(tmp_path, bunny_path, bunny, backend):
    scene = wedge.Scene.from_file(bunny_path, backend=backend)
    assert scene.backend == backend and len(scene) == len(bunny)
    rays = bunny_rays(bunny, 3000).astype(np.float32)
    hits = raycast_hits(tmp_path, bunny_path, rays, "--backend", backend, "--with", "point,normal")
    got = scene.cast_rays(rays, point=True, normal=True)
    assert 500 < (got["prim"] >= 0).sum() < 2900, "the rays should hit and miss"
    assert same_bits(got["t"], hits[:, 0])
    assert same_bits(got["prim"], hits[:, 1].astype(np.int64))
    assert same_bits(got["u"], hits[:, 2]) and same_bits(got["v"], hits[:, 3])
    assert same_bits(got["point"], hits[:, 4:7]) and same_bits(got["normal"], hits[:, 7:10])
    assert got["prim"][:3].tolist() == [-1, -1, -1] and np.isinf(got["t"][:3]).all()


@pytest.mark.parametrize("precision", ["f32", "f64"])
def test_segments_and_any_hit_are_raycast(tmp_path, bunny_path, bunny, precision):
    scene = wedge.Scene.from_file(bunny_path, precision=precision)
    rays = bunny_rays(bunny, 4000, seed=2, segments=True)
    opts = ("--precision", precision)
    closest = raycast_hits(tmp_path, bunny_path, rays, *opts)
    got = scene.cast_rays(rays)
    assert same_bits(got["t"], closest[:, 0]) and same_bits(got["u"], closest[:, 2])
    assert same_bits(got["prim"], closest[:, 1].astype(np.int64))
    anyhit = raycast_hits(tmp_path, bunny_path, rays, *opts, "--any-hit", "--with", "prim")
    hit, prim = scene.occluded(rays, prim=True)
    assert hit.dtype == np.bool_ and same_bits(hit, anyhit[:, 0] == 1)
    assert same_bits(prim, anyhit[:, 1].astype(np.int64))
    assert same_bits(scene.occluded(rays), hit)
    # t_min/t_max cut hits away: fewer than without them, and none outside the segment.
    whole = scene.cast_rays(rays[:, :6])
    assert (got["prim"] >= 0).sum() < (whole["prim"] >= 0).sum()
    inside = got["prim"] >= 0
    assert (got["t"][inside] >= rays[inside, 6].astype(precision.replace("f", "float"))).all()


def test_arrays_and_layouts(bunny):
    rays = bunny_rays(bunny, 500)
    want = bunny.cast_rays(rays)
    # Built from arrays (ints for vertices, uint32 faces) as from the file.
    again = wedge.Scene(bunny.vertices, bunny.faces.astype(np.uint32))
    assert same_bits(again.cast_rays(rays)["t"], want["t"])
    # A strided view is read as np.save would write it (C order), like raycast's file.
    wide = np.zeros((500, 12))
    wide[:, ::2] = rays
    assert same_bits(bunny.cast_rays(wide[:, ::2])["t"], want["t"])
    assert same_bits(bunny.cast_rays(rays[::-1])["t"], want["t"][::-1])
    # float32 rays are the float64 rays rounded, as in raycast.
    f32 = rays.astype(np.float32)
    assert same_bits(bunny.cast_rays(f32)["t"], bunny.cast_rays(f32.astype(np.float64))["t"])
    assert bunny.cast_rays(np.empty((0, 6)))["t"].shape == (0,)


def raycast_error(tmp_path, bunny_path, array):
    path = tmp_path / "bad.npy"
    np.save(path, array)
    done = run("raycast", bunny_path, path, tmp_path / "out.npy", ok=False)
    assert done.returncode != 0
    line = done.stderr.strip()
    prefix = f"error: {path}: "
    assert line.startswith(prefix), line
    return line[len(prefix):]


@pytest.mark.parametrize(
    "array, error",
    [
        (np.zeros((4, 6), dtype=np.int64), TypeError),
        (np.zeros((4, 6), dtype=">f8"), TypeError),
        (np.zeros((4, 6), dtype=np.float16), TypeError),
        (np.zeros((4, 7)), ValueError),
        (np.zeros(6), ValueError),
        (np.zeros((2, 4, 6)), ValueError),
        (np.asfortranarray(np.zeros((4, 6))), ValueError),
    ],
)
def test_bad_rays_fail_as_in_raycast(tmp_path, bunny_path, bunny, array, error):
    message = raycast_error(tmp_path, bunny_path, array)
    for call in (bunny.cast_rays, bunny.occluded):
        with pytest.raises(error) as e:
            call(array)
        assert str(e.value) == message


def test_other_bad_input(tmp_path, bunny):
    with pytest.raises(TypeError, match="expected a numpy array"):
        bunny.cast_rays([[0, 0, 0, 0, 0, 1]])
    with pytest.raises(ValueError, match=r"^unknown back end 'nope' \(expected one of la, "):
        wedge.Scene(bunny.vertices, bunny.faces, backend="nope")
    with pytest.raises(ValueError, match=r"^unknown precision 'f16'"):
        wedge.Scene(bunny.vertices, bunny.faces, precision="f16")
    with pytest.raises(ValueError, match=r"^faces: face 0 has vertex index 99: 3 vertices$"):
        wedge.Scene(np.eye(3), [[0, 1, 99]])
    with pytest.raises(ValueError, match=r"^faces: face 0 has vertex index -1"):
        wedge.Scene(np.eye(3), [[0, 1, -1]])
    with pytest.raises(TypeError, match=r"^faces: dtype float64: expected integers$"):
        wedge.Scene(np.eye(3), np.zeros((1, 3)))
    with pytest.raises(ValueError, match=r"^vertices: shape \(3, 2\): expected \(N, 3\)$"):
        wedge.Scene(np.zeros((3, 2)), [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"^vertices: vertex 1 has coordinate NaN$"):
        wedge.Scene([[0, 0, 0], [np.nan, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"^faces: the mesh has no faces$"):
        wedge.Scene(np.eye(3), np.zeros((0, 3), dtype=int))
    with pytest.raises(ValueError, match=r"beyond f32's range .*use precision=\"f64\"$"):
        wedge.Scene([[0, 0, 0], [1e39, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    big = wedge.Scene([[0, 0, 0], [1e39, 0, 0], [0, 1, 0]], [[0, 1, 2]], precision="f64")
    assert big.precision == "f64"
    missing = tmp_path / "missing.obj"
    with pytest.raises(FileNotFoundError) as e:
        wedge.Scene.from_file(missing)
    assert str(e.value) == f"{missing}: file not found"
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nf 1 2 3\n")
    with pytest.raises(ValueError) as e:
        wedge.Scene.from_file(bad)
    line = run("raytrace", bad, tmp_path / "x.png", 4, 4, ok=False).stderr.strip()
    assert line == f"error: {e.value}"


@pytest.mark.parametrize("mode", ["alpha", "depth", "normal", "shade", "prim"])
def test_render_is_raytrace_bit_for_bit(tmp_path, bunny_path, bunny, mode):
    out = tmp_path / "frame.npy"
    run("raytrace", bunny_path, out, 96, 64, "--mode", mode, "--quiet")
    assert same_bits(bunny.render(96, 64, mode=mode), np.load(out))


def test_render_camera_options(tmp_path, bunny_path, bunny):
    out = tmp_path / "frame.npy"
    view = ("--eye", "0.3,0.2,-0.2", "--look-at", "0,0.1,0", "--up", "0,0,1", "--fov", "30")
    run("raytrace", bunny_path, out, 40, 30, "--mode", "depth", "--quiet", *view)
    got = bunny.render(40, 30, "depth", eye=(0.3, 0.2, -0.2), look_at=(0, 0.1, 0),
                       up=(0, 0, 1), fov=30)
    assert same_bits(got, np.load(out))
    with pytest.raises(ValueError, match=r"^unknown mode 'x' \(expected alpha, "):
        bunny.render(8, 8, mode="x")
    with pytest.raises(ValueError, match=r"^unknown camera 'top'"):
        bunny.render(8, 8, camera="top")
    with pytest.raises(ValueError, match=r"^bad camera: the camera's eye and look-at point"):
        bunny.render(8, 8, eye=(0, 0, 0), look_at=(0, 0, 0))
    with pytest.raises(ValueError, match=r"^camera auto: field of view 200 degrees"):
        bunny.render(8, 8, fov=200)
    with pytest.raises(ValueError):
        bunny.render(0, 8)


def test_gil_is_released(bunny):
    rays = bunny_rays(bunny, 1_000_000, seed=3)
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1

    counter = threading.Thread(target=count)
    counter.start()
    try:
        time.sleep(0.05)
        start = time.perf_counter()
        before = ticks[0]
        bunny.cast_rays(rays)
        during = ticks[0] - before
        elapsed = time.perf_counter() - start
    finally:
        stop.set()
        counter.join()
    # With the GIL held for the whole call the counter could not run at all (it only gets
    # the GIL between bytecodes of this thread); released, it counts all along.
    assert elapsed > 0.02, "the cast was too short to tell"
    assert during > 10_000, f"{during} counts in {elapsed:.3f} s"


def test_threads_share_a_scene(bunny):
    rays = [bunny_rays(bunny, 20_000, seed=s) for s in range(6)]
    want = [bunny.cast_rays(r)["t"] for r in rays]
    got = [None] * len(rays)

    def work(k):
        got[k] = bunny.cast_rays(rays[k])["t"]

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(rays))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(same_bits(g, w) for g, w in zip(got, want))


def test_readme_example_runs(bunny_path, capsys, monkeypatch):
    text = (REPO / "python" / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the README has no example"
    monkeypatch.chdir(REPO)
    for block in blocks:
        exec(compile(block, "README.md", "exec"), {})
    printed = capsys.readouterr().out
    assert re.search(r"\d+ of \d+ pixels differ", printed), printed
    assert re.search(r"\d+ of \d+ rays differ", printed), printed


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_raycast_reads_and_writes_every_layout_numpy_does(tmp_path, bunny_path, bunny, dtype):
    rays = bunny_rays(bunny, 3000, seed=3, segments=True).astype(dtype)
    expected = raycast_hits(tmp_path, bunny_path, rays)
    ext = "f32" if dtype == np.float32 else "f64"
    written = {
        "savez.npz": lambda p: np.savez(p, rays),
        "compressed.npz": lambda p: np.savez_compressed(p, rays=rays, other=np.zeros(3)),
        f"raw.{ext}": rays.tofile,
    }
    for name, save in written.items():
        path = tmp_path / name
        save(path)
        options = () if name.endswith("npz") else ("--ray-columns", "8")
        for out, load in [
            ("hits.npz", lambda p: np.load(p)["hits"]),
            ("hits.f64", lambda p: np.fromfile(p, dtype="<f8").reshape(-1, 4)),
        ]:
            run("raycast", bunny_path, path, tmp_path / out, "--quiet", *options)
            assert same_bits(load(tmp_path / out), expected), (name, out)
