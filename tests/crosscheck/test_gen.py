"""Cross-checks of `solidkit gen` against independent tools.

- platonic and sponge: manifold3d (double-precision `Mesh64`) agrees with `solidkit check` on
  every file: closed manifold (status NoError), genus, volume within 1e-9 relative, and both
  agree with the manifest's exact truth;
- random --seed 7: manifold3d accepts every mesh (NoError) and its volume is within the stated
  tolerance of the sampled volume;
- broken: counts measured with trimesh's arrays (boundary, non-manifold and inconsistent edges,
  degenerate faces, shells, V/E/F) and admesh's report (disconnected edges, backwards edges,
  degenerate facets, volume) agree with the manifest's expected defects and `solidkit check`;
- a 3MF and a GLB of the same solid load in trimesh with the same vertex and triangle counts and
  volume.

The binary comes from SOLIDKIT_BIN. Needs numpy, trimesh, manifold3d, lxml and networkx
(trimesh's 3MF loader), pytest, and the Debian `admesh` binary.
"""

import json
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

trimesh = pytest.importorskip("trimesh")
manifold3d = pytest.importorskip("manifold3d")

BIN = os.environ.get("SOLIDKIT_BIN")
pytestmark = pytest.mark.skipif(not BIN, reason="SOLIDKIT_BIN is not set")


def generate(root, suite, *args):
    """Runs `solidkit gen SUITE -o root/NAME ARGS` and returns (folder, manifest)."""
    folder = root / ("_".join((suite,) + args).replace("-", "") or suite)
    subprocess.run([BIN, "gen", suite, "-o", str(folder), *args], check=True, capture_output=True)
    with open(folder / "manifest.json") as f:
        return folder, json.load(f)


def check(path):
    """`solidkit check --json` of a file (exit 0 or 1) as a dict."""
    out = subprocess.run([BIN, "check", "--json", str(path)], capture_output=True, text=True)
    assert out.returncode in (0, 1), out.stderr
    return json.loads(out.stdout)


def load(path):
    return trimesh.load(str(path), process=False, force="mesh")


def to_manifold(mesh):
    return manifold3d.Manifold(
        manifold3d.Mesh64(
            vert_properties=np.asarray(mesh.vertices, dtype=np.float64),
            tri_verts=np.asarray(mesh.faces, dtype=np.uint64),
        )
    )


def rel(a, b):
    return abs(a - b) / abs(b)


@pytest.fixture(scope="module")
def root(tmp_path_factory):
    return tmp_path_factory.mktemp("gen")


@pytest.mark.parametrize("suite", ["platonic", "sponge"])
def test_exact_suites_agree_with_manifold3d(root, suite):
    folder, manifest = generate(root, suite)
    for solid in manifest["solids"]:
        path = folder / solid["file"]
        report = check(path)
        assert report["closed"] and report["manifold"] and report["oriented"], solid["name"]
        m = to_manifold(load(path))
        assert m.status() == manifold3d.Error.NoError, solid["name"]
        assert m.genus() == report["genus"] == solid["truth"]["genus"], solid["name"]
        assert m.num_vert() == report["vertices"] == solid["truth"]["vertices"]
        assert m.num_tri() == report["faces"] == solid["truth"]["faces"]
        assert rel(m.volume(), report["volume"]) <= 1e-9, solid["name"]
        assert rel(report["volume"], solid["truth"]["volume"]["value"]) <= 1e-9, solid["name"]
        assert rel(m.surface_area(), solid["truth"]["area"]["value"]) <= 1e-9, solid["name"]


def test_random_meshes_are_accepted_by_manifold3d(root):
    folder, manifest = generate(root, "random", "--seed", "7")
    assert len(manifest["solids"]) == 8
    for solid in manifest["solids"]:
        m = to_manifold(load(folder / solid["file"]))
        assert m.status() == manifold3d.Error.NoError, solid["name"]
        sampled = solid["truth"]["volume"]["value"]
        assert abs(m.volume() - sampled) <= solid["error"]["volume_tolerance"], solid["name"]
        assert os.path.exists(folder / solid["tree"])


def trimesh_counts(mesh):
    """The report's counts, measured with trimesh's arrays (triangles with a repeated index are
    left out of the topology and counted as degenerate, as `solidkit check` does)."""
    faces = np.asarray(mesh.faces)
    repeated = (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (faces[:, 0] == faces[:, 2])
    usable = faces[~repeated]
    sub = trimesh.Trimesh(mesh.vertices, usable, process=False)
    directed = sub.edges
    undirected, inverse, per_edge = np.unique(
        np.sort(directed, axis=1), axis=0, return_inverse=True, return_counts=True
    )
    inverse = inverse.reshape(-1)
    # A two-triangle edge is inconsistent when both traverse it the same way.
    inconsistent = 0
    for e in np.flatnonzero(per_edge == 2):
        a, b = directed[inverse == e]
        inconsistent += int((a == b).all())
    referenced = np.unique(usable)
    shells = len(trimesh.graph.connected_components(undirected, nodes=referenced))
    area = sub.area_faces
    longest = np.max(
        np.linalg.norm(sub.triangles - np.roll(sub.triangles, 1, axis=1), axis=2), axis=1
    )
    flat = int(np.sum(2 * area <= 1e-12 * longest**2))
    return {
        "vertices": len(referenced),
        "edges": len(undirected),
        "faces": len(usable),
        "shells": shells,
        "boundary_edges": int(np.sum(per_edge == 1)),
        "non_manifold_edges": int(np.sum(per_edge > 2)),
        "inconsistent_edges": inconsistent,
        "degenerate_faces": flat + int(np.sum(repeated)),
    }


def admesh_counts(path):
    out = subprocess.run(["admesh", "-e", str(path)], capture_output=True, text=True, check=True).stdout
    number = lambda label: float(re.search(re.escape(label) + r"\s*:\s*([-0-9.]+)", out).group(1))
    disconnected = sum(
        k * number(f"Facets with {k} disconnected edge" + ("s" if k > 1 else "")) for k in (1, 2, 3)
    )
    return {
        "disconnected_edges": int(disconnected),
        "backwards_edges": int(number("Backwards edges")),
        "degenerate_facets": int(number("Degenerate facets")),
        "volume": number("Volume"),
    }


def test_broken_counts_agree_with_trimesh_and_admesh(root):
    ply, manifest = generate(root, "broken", "--format", "ply")
    stl, _ = generate(root, "broken", "--format", "stl")
    for solid in manifest["solids"]:
        name = solid["name"]
        expected = solid["defects"]["expected"]
        report = check(ply / solid["file"])
        counts = trimesh_counts(load(ply / solid["file"]))
        for key, value in counts.items():
            assert value == expected[key] == report[key], (name, key, value, expected[key], report[key])
        if shutil.which("admesh") is None:
            continue
        a = admesh_counts(stl / f"{name}.stl")
        kinds = [d["kind"] for d in solid["defects"]["put_in"]]
        # admesh drops facets with coincident corners and counts them as degenerate.
        assert a["degenerate_facets"] == kinds.count("repeated_index_face"), name
        # admesh counts a backwards edge once from each of its two facets.
        assert a["backwards_edges"] == 2 * expected["inconsistent_edges"], name
        if expected["non_manifold_edges"] == 0:
            assert a["disconnected_edges"] == expected["boundary_edges"], name
        if expected["closed"] and expected["manifold"] and expected["oriented"]:
            assert abs(a["volume"] - report["volume"]) < 1e-5, name


@pytest.mark.parametrize("suite", ["platonic", "csg"])
def test_3mf_and_glb_load_alike_in_trimesh(root, suite):
    three, manifest = generate(root, suite, "--format", "3mf")
    glb, _ = generate(root, suite, "--format", "glb")
    for solid in manifest["solids"]:
        a = load(three / solid["file"])
        b = load(glb / (solid["name"] + ".glb"))
        assert len(a.vertices) == len(b.vertices) == solid["mesh"]["vertices"], solid["name"]
        assert len(a.faces) == len(b.faces) == solid["mesh"]["faces"], solid["name"]
        assert rel(a.volume, solid["mesh"]["volume"]) <= 1e-9, solid["name"]
        assert rel(b.volume, a.volume) <= 1e-5, solid["name"]
