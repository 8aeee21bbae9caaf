"""OpenSCAD (Debian's openscad 2021.01, exact CGAL Booleans): the tree written as a .scad file
and exported with `openscad -o out.stl`. Its own primitives where it has them (sphere, cube,
cylinder and cones, torus by rotate_extrude of a circle, linear_extrude with twist and scale,
rotate_extrude, prisms), `polyhedron()` of the leaf meshes of leaves.py otherwise; transforms
as multmatrix. Curved primitives get `$fn = openscad_fn` (default 64) fragments; its facet error
is the sagitta of that polygon. Nodes only a field expresses are not expressible here.
"""
import math
import subprocess
import time
from pathlib import Path

import numpy as np

from . import bounds, leaves, meshio, tree
from .tree import NotExpressible

NATIVE = {"sphere", "box", "cylinder", "cone", "torus", "extrude", "revolve", "prism"}


def _num(x) -> str:
    return repr(float(x))


def _vec(v) -> str:
    return "[" + ", ".join(_num(x) for x in v) + "]"


def _polygon(loops) -> str:
    pts, paths, k = [], [], 0
    for loop in loops:
        pts.extend(loop)
        paths.append(list(range(k, k + len(loop))))
        k += len(loop)
    return f"polygon(points={_vec_list(pts)}, paths={paths});"


def _vec_list(pts) -> str:
    return "[" + ", ".join(_vec(p) for p in pts) + "]"


class Writer:
    def __init__(self, ctx):
        self.ctx = ctx
        self.fn = int(ctx.param("openscad_fn", 64))
        c = (ctx.box[0] + ctx.box[1]) / 2
        self.big = 4 * (float(np.linalg.norm(c)) + ctx.diagonal) + 1.0
        self.polyhedra = 0

    def node(self, n: dict, indent: str = "") -> str:
        t = n["type"]
        if t in tree.FIELD_ONLY or t == "gyroid":
            raise NotExpressible(f"'{t}' has no OpenSCAD equivalent")
        kids = tree.children(n)
        inner = indent + "  "
        if t in tree.TRANSFORMS:
            m = tree.matrix(n)
            return f"{indent}multmatrix(m={_vec_list(m)}) {{\n{self.node(kids[0], inner)}{indent}}}\n"
        if t in tree.BOOLEANS:
            body = "".join(self.node(k, inner) for k in kids)
            return f"{indent}{t}() {{\n{body}{indent}}}\n"
        fn = f"$fn={self.fn}"
        if t == "sphere":
            return f"{indent}sphere(r={_num(n['radius'])}, {fn});\n"
        if t == "box":
            return f"{indent}cube(size={_vec(tree.vec3(n['size']))}, center=true);\n"
        if t == "cylinder":
            return f"{indent}cylinder(h={_num(n['height'])}, r={_num(n['radius'])}, center=true, {fn});\n"
        if t == "cone":
            return (f"{indent}cylinder(h={_num(n['height'])}, r1={_num(n['bottom_radius'])}, "
                    f"r2={_num(n['top_radius'])}, center=true, {fn});\n")
        if t == "torus":
            return (f"{indent}rotate_extrude({fn}) translate([{_num(n['major_radius'])}, 0]) "
                    f"circle(r={_num(n['minor_radius'])}, {fn});\n")
        if t == "extrude":
            h = float(n["height"])
            twist = float(n.get("twist", 0))
            slices, max_edge = leaves.twisted_extrusion_steps(n, self.fn)
            loops = leaves.profile_loops(n["profile"], self.fn)
            if max_edge:
                loops = [leaves.subdivide(l, max_edge) for l in loops]
            # OpenSCAD twists clockwise for a positive angle; the format turns counter-clockwise
            prof = _polygon(loops)
            # OpenSCAD drops the points that split long edges (collinear), so only dense slices
            # (20 per degree) keep the skewed side quads small
            slices = max(slices, int(math.ceil(20 * abs(twist))), 1)
            return (f"{indent}translate([0, 0, {_num(-h / 2)}]) linear_extrude(height={_num(h)}, "
                    f"twist={_num(-twist)}, scale={_num(n.get('scale', 1))}, slices={slices}) {prof}\n")
        if t == "revolve":
            prof = _polygon(leaves.profile_loops(n["profile"], self.fn))
            return f"{indent}rotate_extrude(angle={_num(n.get('angle', 360))}, {fn}) {prof}\n"
        if t == "prism":
            d = n["direction"]
            shear = [[1, 0, d[0], 0], [0, 1, d[1], 0], [0, 0, d[2], 0], [0, 0, 0, 1]]
            loops = [n["polygon"]] + list(n.get("holes", []))
            return (f"{indent}multmatrix(m={_vec_list(shear)}) linear_extrude(height=1) "
                    f"{_polygon(loops)}\n")
        # any other leaf: the polyhedron of its leaf mesh (OpenSCAD wants faces clockwise
        # seen from outside)
        m = leaves.leaf(n, self.ctx.base_dir, self.fn, self.big, detail=0.25)
        verts, faces = leaves.to_arrays(m)
        self.polyhedra += 1
        return (f"{indent}polyhedron(points={_vec_list(verts)}, "
                f"faces={np.asarray(faces)[:, ::-1].tolist()}, convexity=10);\n")


def build(ctx, work: Path, timeout: float) -> dict:
    w = Writer(ctx)
    scad = w.node(ctx.root)
    src = Path(work) / "openscad.scad"
    out = Path(work) / "openscad-raw.stl"
    src.write_text(scad)
    start = time.time()
    r = subprocess.run(["openscad", "-o", str(out), str(src)], capture_output=True, text=True,
                       timeout=timeout)
    if r.returncode != 0 or not out.exists():
        raise RuntimeError(f"openscad failed ({r.returncode}): {r.stderr.strip()[-500:]}")
    verts, faces = meshio.read_stl(out)
    return {
        "verts": verts, "faces": faces, "time_s": time.time() - start,
        "method": "CGAL Booleans" + (f", {w.polyhedra} polyhedron leaves" if w.polyhedra else ""),
        "grid": 0.0, "facet_error": leaves.sagitta(bounds.curved_radius(ctx.root, ctx.base_dir), w.fn),
        "own": {}, "settings": {"fn": w.fn},
    }
