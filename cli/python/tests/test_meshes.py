"""Meshes: the pipeline from Python against exact values and the command line; reading,
checking, comparing, generating; conversions to trimesh and manifold3d; progress and Ctrl-C."""

import json
import math
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import solidkit as sk


def test_sphere_volume_and_arrays():
    m = sk.sphere(1).mesh(resolution=96)
    assert m.vertices.dtype == np.float64 and m.vertices.shape[1] == 3
    assert m.faces.dtype == np.int64 and m.faces.shape[1] == 3
    assert len(m) == len(m.faces)
    assert not m.vertices.flags.writeable and not m.faces.flags.writeable
    r = m.report()
    assert r["closed"] and r["manifold"] and r["genus"] == 0
    assert math.isclose(r["volume"], 4 / 3 * math.pi, rel_tol=0.01)
    assert r["warnings"] == []


def test_dual_contouring_keeps_the_cube_exact():
    m = sk.cube(2).mesh(resolution=32, method="dc", tolerance=0.01)
    r = m.report()
    assert r["closed"] and r["genus"] == 0
    assert math.isclose(r["volume"], 8.0, rel_tol=1e-3)
    assert r["faces"] < sk.cube(2).mesh(resolution=32).report()["faces"] / 4


def test_bounds_clip_unbounded_solids():
    m = sk.plane([0, 0, 1], 0).mesh(resolution=32, bounds=((-1, -1, -1), (1, 1, 1)))
    r = m.report()
    assert r["closed"] and math.isclose(r["volume"], 4.0, rel_tol=1e-3)
    with pytest.raises(sk.MeshingError, match="unbounded"):
        sk.plane([0, 0, 1], 0).mesh()


def test_mesh_options_are_range_checked():
    for kw, pattern in [
        ({"resolution": 0}, "resolution"),
        ({"resolution": 100_000}, "resolution"),
        ({"method": "xx"}, "method"),
        ({"tolerance": -1.0, "method": "dc"}, "tolerance"),
        ({"refine": 3}, "refine"),
        ({"threads": 10**9}, "threads"),
        ({"bounds": ((1, 1, 1), (0, 0, 0))}, "bounds"),
    ]:
        with pytest.raises(ValueError, match=pattern):
            sk.sphere(1).mesh(**kw)
    with pytest.raises(sk.MeshingError, match="dc"):
        sk.sphere(1).mesh(tolerance=0.1)
    with pytest.raises(sk.MeshingError, match="memory"):
        sk.sphere(1).mesh(resolution=2048, max_memory=1 << 20)


@pytest.mark.filterwarnings("ignore:features thinner")
def test_report_keys_and_values_match_the_command_line(tmp_path, solidkit_bin, fixtures):
    tree = fixtures / "bench" / "gyroid-sphere.json"
    out = subprocess.run(
        [solidkit_bin, "mesh", str(tree), "--resolution", "64", "--json", "--no-progress"],
        check=True, capture_output=True, text=True,
    )
    cli = json.loads(out.stdout)
    py = sk.load(tree).mesh(resolution=64).report()
    cli_only = {"time_s", "report_time_s", "tolerance"}
    assert set(cli) - cli_only <= set(py)
    for key in ["vertices", "faces", "edges", "shells", "genus", "closed", "manifold",
                "self_intersections", "cells", "cell", "refinement", "volume", "area", "bbox"]:
        assert py[key] == cli[key], key
    # The gyroid's sheet is thinner than a cell at 64: both say that fragments split off.
    fragments = [["shells are at most" in w for w in r["warnings"]] for r in (cli, py)]
    assert any(fragments[0]) and fragments[0] == fragments[1], (cli["warnings"], py["warnings"])


def test_target_error_makes_small_meshes_like_the_command_line(tmp_path, solidkit_bin):
    tree = tmp_path / "box.json"
    tree.write_text(json.dumps({"format": "solidkit-tree", "version": 1,
                                "root": {"type": "box", "size": [1, 1, 1]}}))
    out = subprocess.run(
        [solidkit_bin, "mesh", str(tree), "--resolution", "32", "--target-error", "0.002",
         "--json", "--no-progress"],
        check=True, capture_output=True, text=True,
    )
    cli = json.loads(out.stdout)
    m = sk.load(tree).mesh(resolution=32, target_error=0.002)
    r = m.report()
    assert r["method"] == "dc" and r["target_error"] == 0.002 and r["simplify"] == 0.002
    assert r["simplify_collapses"] > 0
    assert len(m.faces) <= 48 and len(m.faces) == cli["faces"]
    assert r["closed"] and r["manifold"] and r["genus"] == 0
    # within area x E of the exact volume, and the same mesh as the command line's
    assert abs(r["volume"] - 1.0) < 6 * 0.002 and r["volume"] == cli["volume"]
    plain = sk.load(tree).mesh(resolution=32)
    assert plain.report()["simplify"] is None and len(plain.faces) > 1000
    for bad in [0.0, -1.0, float("nan")]:
        with pytest.raises(ValueError, match="target_error"):
            sk.box(1).mesh(target_error=bad)


def test_save_read_check_and_compare(tmp_path):
    m = (sk.sphere(1) - sk.cube(1.2)).mesh(resolution=48)
    for ext in ["stl", "ply", "obj", "off"]:
        path = tmp_path / f"m.{ext}"
        m.save(path)
        back = sk.read(path)
        r = back.report()
        assert r["closed"] and r["genus"] == 7, ext
        d = sk.compare(m, back, samples=5000)
        assert d["hausdorff"]["symmetric"] < 1e-6, ext
    r = sk.check(m.vertices, m.faces)
    assert r["closed"] and r["self_intersections"] == 0
    # One face removed: three boundary edges, not closed.
    r = sk.check(m.vertices, m.faces[1:])
    assert not r["closed"] and r["boundary_edges"] == 3
    with pytest.raises(ValueError, match="refers to vertex"):
        sk.check(m.vertices[:3], m.faces)
    with pytest.raises(sk.MeshIOError):
        sk.read(tmp_path / "missing.stl")


def test_gen_writes_a_suite_with_its_manifest(tmp_path):
    manifest = sk.gen("platonic", tmp_path, format="stl")
    assert len(manifest["solids"]) == 14
    assert json.loads((tmp_path / "manifest.json").read_text()) == manifest
    for solid in manifest["solids"]:
        assert (tmp_path / solid["file"]).exists()
    with pytest.raises(ValueError, match="unknown suite"):
        sk.gen("nope", tmp_path)


def test_round_trip_through_trimesh_and_manifold3d():
    trimesh = pytest.importorskip("trimesh")
    m3d = pytest.importorskip("manifold3d")
    m = (sk.sphere(1) - sk.box(1.2)).mesh(resolution=64)
    r = m.report()
    tm = m.to_trimesh()
    assert isinstance(tm, trimesh.Trimesh) and tm.is_watertight
    man = sk.Mesh.from_trimesh(tm).to_manifold()
    assert man.status() == m3d.Error.NoError
    assert man.genus() == r["genus"] == 7
    assert math.isclose(man.volume(), r["volume"], rel_tol=1e-5)
    back = sk.Mesh.from_manifold(man).report()
    assert back["genus"] == 7 and back["closed"]


def test_progress_is_reported_and_an_exception_in_it_cancels():
    seen = []
    sk.sphere(1).mesh(resolution=256, progress=lambda stage, done, total: seen.append((stage, done, total)))
    assert seen and all(0 <= d <= t for _, d, t in seen)

    class Stop(Exception):
        pass

    def stop(stage, done, total):
        raise Stop()

    start = time.monotonic()
    with pytest.raises(Stop):
        (sk.gyroid(0.2) & sk.sphere(2)).mesh(resolution=1024, progress=stop)
    assert time.monotonic() - start < 5


def test_ctrl_c_stops_a_long_mesh_with_keyboard_interrupt():
    code = textwrap.dedent("""
        import signal, sys, time, numpy as np, solidkit as sk
        # A process started in the background by a shell inherits SIGINT ignored: restore
        # Python's own handler, as in an interactive session.
        signal.signal(signal.SIGINT, signal.default_int_handler)
        rng = np.random.default_rng(1)
        balls = [sk.sphere(0.15).translate(c) for c in rng.uniform(-2, 2, (300, 3)).tolist()]
        slow = sk.union(*balls) | (sk.gyroid(0.1) & sk.sphere(2))
        print("start", flush=True)
        t = time.monotonic()
        try:
            # About 8 s on one thread when not interrupted.
            slow.mesh(resolution=768, refine=1, threads=1)
        except KeyboardInterrupt:
            print(f"interrupted after {time.monotonic() - t:.2f}", flush=True)
            sys.exit(3)
        print("finished", flush=True)
    """)
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "start"
    time.sleep(1.0)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=30)
    assert p.returncode == 3, out
    assert time.monotonic() - sent < 3, "the mesher should stop soon after Ctrl-C"


def test_colours_reach_face_colors_the_report_and_saved_files(tmp_path):
    red_cube = sk.box((10, 10, 10)).color("red")
    blue_ball = sk.sphere(6.5).color([0, 0, 1])
    m = (red_cube - blue_ball).mesh(resolution=48)
    c = m.face_colors
    assert c.dtype == np.uint8 and c.shape == (len(m.faces), 4)
    centroids = m.vertices[m.faces].mean(axis=1)
    on_cube = np.abs(np.abs(centroids).max(axis=1) - 5) < 0.02
    on_ball = np.abs(np.linalg.norm(centroids, axis=1) - 6.5) < 0.05
    assert (c[on_cube & ~on_ball] == [255, 0, 0, 255]).all()
    assert (c[on_ball & ~on_cube] == [0, 0, 255, 255]).all()
    assert m.report()["colors"] == 2
    plain = (sk.box((10, 10, 10)) - sk.sphere(6.5)).mesh(resolution=48)
    assert plain.face_colors is None and plain.report()["colors"] == 0
    assert np.array_equal(plain.faces, m.faces) and np.array_equal(plain.vertices, m.vertices)
    m.save(tmp_path / "c.3mf")
    assert b"basematerials" in (tmp_path / "c.3mf").read_bytes()
    m.save(tmp_path / "n.3mf", colors=False)
    plain.save(tmp_path / "p.3mf")
    assert (tmp_path / "n.3mf").read_bytes() == (tmp_path / "p.3mf").read_bytes()
    with pytest.raises(ValueError, match="unknown colour"):
        sk.sphere(1).color("nosuchcolour")
    with pytest.raises(ValueError):
        sk.sphere(1).color([2, 0, 0])
    inner = sk.sphere(1).color("lime").color("red", 0.5).mesh(resolution=16).face_colors
    assert (inner == [0, 255, 0, 255]).all()


def test_polyhedral_booleans_are_exact():
    # A box minus a box flush with three of its faces: exact, a few dozen triangles, no grid.
    solid = sk.box(2) - sk.box([2, 1, 1]).translate([1, 0, 0])
    m = solid.mesh(method="polyhedral")
    r = m.report()
    assert r["closed"] and r["manifold"] and r["genus"] == 0
    assert math.isclose(r["volume"], 7.0, rel_tol=1e-12)
    assert r["faces"] < 100
    assert r["method"] == "polyhedral"
    # A sphere is gridded alone (a warning says so) and cut exactly from the box: genus 5.
    with pytest.warns(UserWarning, match="not a polyhedron"):
        m = (sk.box(2) - sk.sphere(1.2)).mesh(method="polyhedral", resolution=64)
    assert m.report()["genus"] == 5
    with pytest.raises(ValueError, match="tolerance"):
        sk.box(1).mesh(method="polyhedral", tolerance=0.1)
