"""Trees from Python: the builder mirrors Rust, Rhai and JSON; loading names file, line and
column; warnings reach Python; files stay confined to the tree's folder."""

import json
import math
import warnings

import pytest

import solidkit as sk


def test_acceptance_sphere_minus_cube_has_genus_7():
    m = (sk.sphere(1) - sk.box(1.2)).mesh(resolution=128)
    r = m.report()
    assert r["genus"] == 7
    assert r["closed"] and r["manifold"] and r["oriented"]
    assert r["shells"] == 1


def test_operators_and_functions_build_the_same_trees():
    a, b = sk.sphere(1), sk.cube([1, 2, 3]).translate([0.5, 0, 0])
    assert (a | b).to_json() == sk.union(a, b).to_json()
    assert (a & b).to_json() == sk.intersection(a, b).to_json()
    assert (a - b).to_json() == sk.difference(a, b).to_json()
    assert sk.box(2).to_json() == sk.cube(2).to_json() == sk.cuboid([2, 2, 2]).to_json()


def test_python_tree_equals_the_same_rhai_script(tmp_path):
    script = tmp_path / "part.rhai"
    script.write_text(
        "let s = sphere(1.0).translate([1.0, 0.0, 0.0]);\n"
        "let c = cylinder(0.5, 3.0).rotate([1.0, 0.0, 0.0], 90.0);\n"
        "smooth_union(s - c, torus(2.0, 0.25), 0.1)\n"
    )
    from_rhai = sk.load(script)
    s = sk.sphere(1.0).translate([1, 0, 0])
    c = sk.cylinder(0.5, 3.0).rotate([1, 0, 0], 90)
    from_python = sk.smooth_union(s - c, sk.torus(2, 0.25), radius=0.1)
    assert from_python.to_json() == from_rhai.to_json()


def test_to_json_round_trips_through_the_cli_format():
    part = (sk.sphere(1).scale([1, 2, 1]) - sk.plane([0, 0, 1], 0.5)).shell(0.1)
    again = sk.from_json(part.to_json())
    assert again.to_json() == part.to_json()
    pts = [[0.0, 0.0, 0.0], [0.3, 1.2, 0.1], [2, 2, 2]]
    assert list(part.eval(pts, double=True)) == list(again.eval(pts, double=True))


def test_node_reaches_every_family_and_embeds_solids():
    ring = sk.node("revolve", profile={"type": "circle", "center": [2, 0], "radius": 0.5})
    r = ring.mesh(resolution=96).report()
    assert r["genus"] == 1
    assert math.isclose(r["volume"], 2 * math.pi * 2 * math.pi * 0.25, rel_tol=0.02)
    blob = sk.node(
        "blob",
        threshold=0.5,
        balls=[{"center": [-0.5, 0, 0], "strength": 1, "sharpness": 3},
               {"center": [0.5, 0, 0], "strength": 1, "sharpness": 3}],
    )
    assert blob.mesh(resolution=48).report()["shells"] == 1
    wrapped = sk.node({"type": "union"}, children=[sk.sphere(1), sk.sphere(1).translate([3, 0, 0])])
    assert wrapped.mesh(resolution=64).report()["shells"] == 2


def test_bad_parameters_and_nodes_raise_with_the_offending_key():
    with pytest.raises(ValueError, match="radius"):
        sk.sphere(-1)
    with pytest.raises(sk.LoadError, match="unknown node type"):
        sk.node("blobby", threshold=1)
    with pytest.raises(ValueError, match="not a Solid"):
        sk.union(sk.sphere(1), 3)


def test_load_errors_name_file_line_and_column(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"type": "union",\n "children": [ {"type": "sphere", "radius": } ]}')
    with pytest.raises(sk.LoadError) as e:
        sk.load(bad)
    assert str(e.value).startswith(f"{bad}:2:")
    with pytest.raises(sk.LoadError, match="unsupported input format"):
        sk.load(tmp_path / "x.txt")
    assert issubclass(sk.LoadError, sk.SolidkitError)


def test_openscad_warnings_reach_python(tmp_path):
    f = tmp_path / "m.csg"
    # A sphere of infinite radius: OpenSCAD warns, skips it and renders the rest.
    f.write_text("group() {\n cube(size = [1, 1, 1], center = false);\n sphere(r = inf);\n}\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        s = sk.load(f)
    assert s.warnings, "the .csg front end should warn about the empty extrusion"
    assert any(str(w.message) in s.warnings for w in caught)
    assert math.isclose(s.mesh(resolution=32).report()["volume"], 1.0, rel_tol=1e-3)


def test_files_named_by_a_tree_stay_in_its_folder(tmp_path):
    inner = tmp_path / "inner"
    inner.mkdir()
    sk.sphere(1).mesh(resolution=16).save(tmp_path / "outside.stl")
    tree = inner / "t.json"
    tree.write_text(json.dumps({"type": "mesh", "path": "../outside.stl"}))
    with pytest.raises(sk.LoadError, match="outside"):
        sk.load(tree)
    assert sk.load(tree, allow=[tmp_path]).bbox[1][0] > 0.9


def test_scad_files_load_through_openscad_with_defines(tmp_path):
    import shutil

    f = tmp_path / "m.scad"
    f.write_text("s = 1;\ncube([s, 2, 3]);\n")
    if shutil.which("openscad") is None:
        with pytest.raises(sk.LoadError, match="openscad is not installed"):
            sk.load(f)
        return
    assert list(sk.load(f).bbox[1]) == [1.0, 2.0, 3.0]
    assert list(sk.load(f, defines=["s=5"]).bbox[1]) == [5.0, 2.0, 3.0]


def test_formula_solids_through_node():
    # The implicit equation of a torus, cut by its box: genus 1, volume 2 pi^2 R r^2.
    torus = sk.node("expr", formula="(sqrt(x^2 + y^2) - 1)^2 + z^2 - 0.3^2",
                    bounds=[[-1.5, -1.5, -0.5], [1.5, 1.5, 0.5]])
    r = torus.mesh(resolution=96).report()
    assert r["genus"] == 1 and r["closed"]
    assert abs(r["volume"] - 2 * math.pi ** 2 * 0.09) < 0.01 * 2 * math.pi ** 2 * 0.09
    with pytest.raises(sk.LoadError, match="unknown name 'q'"):
        sk.node("expr", formula="x + q", bounds=[[0, 0, 0], [1, 1, 1]])


def test_parametric_surfaces_through_node():
    # The notes' z = sin(uv) over [-2, 2]^2 on the base z = -1.5: volume 16 x 1.5 (sin(uv) is odd).
    hill = sk.node("param_surface", z="sin(u*v)", u=[-2, 2], v=[-2, 2], base=-1.5)
    r = hill.mesh(resolution=96).report()
    assert r["closed"] and r["shells"] == 1
    assert abs(r["volume"] - 24.0) < 0.01 * 24.0
    # A flat bilinear Bezier patch 2 x 3 thickened by 0.25: area x thickness.
    slab = sk.node("bezier_patch", points=[[[0, 0, 0], [2, 0, 0]], [[0, 3, 0], [2, 3, 0]]],
                   thickness=0.25)
    assert abs(slab.mesh(resolution=96).report()["volume"] - 1.5) < 0.02 * 1.5
    with pytest.raises(sk.LoadError, match="give \"thickness\" or \"base\""):
        sk.node("bezier_patch", points=[[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 0]]])
    # The same hill tessellated adaptively: the same solid.
    adaptive = sk.node("param_surface", z="sin(u*v)", u=[-2, 2], v=[-2, 2], base=-1.5,
                       tessellation="adaptive")
    r = adaptive.mesh(resolution=96).report()
    assert r["closed"] and r["shells"] == 1
    assert abs(r["volume"] - 24.0) < 0.01 * 24.0
    with pytest.raises(sk.LoadError, match="tessellation"):
        sk.node("param_surface", z="u", u=[0, 1], v=[0, 1], base=-1, tessellation="fine")


def test_rhai_scripts_take_defines_as_constants(tmp_path):
    f = tmp_path / "m.rhai"
    f.write_text('let n = if is_def_var("n") { n } else { 1.0 };\nbox([n, size[1], 3.0])\n')
    assert list(sk.load(f, defines=["n=4.0", "size=[1, 2]"]).bbox[1]) == [2.0, 1.0, 1.5]
    assert list(sk.load(f, defines=["size=[1, 6]"]).bbox[1]) == [0.5, 3.0, 1.5]
    with pytest.raises(sk.LoadError, match="not a Rhai literal"):
        sk.load(f, defines=["size=oops"])
    t = tmp_path / "t.json"
    t.write_text('{"type": "sphere", "radius": 1}')
    with pytest.raises(sk.LoadError, match="applies to .scad and .rhai inputs only"):
        sk.load(t, defines=["n=1"])
