"""The field of a JSON subtree (negative inside), written here from the format's definitions
(docs/json-format.md and the kernel's documented formulas: quadratic smooth minimum
`min(a, b) − r·h²/4`, `h = max(r − |a − b|, 0)/r`; offset `f − d`; shell `|f| − t/2`; transforms
`σ·f(M⁻¹ p)` with σ the smallest singular value) as straight-line Python source, compiled twice:
over numpy arrays (dense grids for OpenVDB) and over floats (manifold3d's scalar level-set
callback, which numpy would slow down twenty-fold).

Primitive fields are exact distances where that is short to write (sphere, box, cylinder, torus,
plane) and sign-correct bounds otherwise (cone, ellipsoid, gyroid, blob): the level sets only
need the sign and a field that is roughly linear across a cell.
"""
import math

import numpy as np

from . import tree

SCALAR = {"MIN": min, "MAX": max, "ABS": abs, "SQRT": math.sqrt, "SIN": math.sin,
          "COS": math.cos, "EXP": math.exp, "POS": lambda v: v if v > 0.0 else 0.0}
VECTOR = {"MIN": np.minimum, "MAX": np.maximum, "ABS": np.abs, "SQRT": np.sqrt, "SIN": np.sin,
          "COS": np.cos, "EXP": np.exp, "POS": lambda v: np.maximum(v, 0.0)}


class _Gen:
    def __init__(self):
        self.lines = []
        self.n = 0

    def var(self, expr: str) -> str:
        self.n += 1
        name = f"v{self.n}"
        self.lines.append(f"    {name} = {expr}")
        return name

    def fold(self, values, op):
        acc = values[0]
        for v in values[1:]:
            acc = self.var(f"{op}({acc}, {v})")
        return acc

    def smin(self, a, b, r):
        h = self.var(f"POS({r!r} - ABS({a} - {b})) / {r!r}")
        return self.var(f"MIN({a}, {b}) - {h} * {h} * {r!r} * 0.25")

    def node(self, n: dict, x: str, y: str, z: str) -> str:
        t = n["type"]
        kids = tree.children(n)
        if t in tree.TRANSFORMS:
            m = tree.matrix(n)
            inv = np.linalg.inv(m)
            sigma = float(np.linalg.svd(m[:3, :3], compute_uv=False).min())
            c = []
            for i in range(3):
                r = inv[i]
                c.append(self.var(f"{r[0]!r} * {x} + {r[1]!r} * {y} + {r[2]!r} * {z} + {r[3]!r}"))
            v = self.node(kids[0], *c)
            return self.var(f"{sigma!r} * {v}")
        if t == "union":
            return self.fold([self.node(k, x, y, z) for k in kids], "MIN")
        if t == "intersection":
            return self.fold([self.node(k, x, y, z) for k in kids], "MAX")
        if t == "difference":
            vals = [self.node(k, x, y, z) for k in kids]
            return self.fold([vals[0]] + [self.var(f"-{v}") for v in vals[1:]], "MAX")
        if t in ("smooth_union", "smooth_intersection", "smooth_difference"):
            r = float(n["radius"])
            vals = [self.node(k, x, y, z) for k in kids]
            if t == "smooth_intersection":
                vals = [self.var(f"-{v}") for v in vals]
            elif t == "smooth_difference":
                vals[0] = self.var(f"-{vals[0]}")
            acc = vals[0]
            for v in vals[1:]:
                acc = self.smin(acc, v, r)
            return acc if t == "smooth_union" else self.var(f"-{acc}")
        if t == "offset":
            v = self.fold([self.node(k, x, y, z) for k in kids], "MIN")
            return self.var(f"{v} - {float(n['distance'])!r}")
        if t == "shell":
            v = self.fold([self.node(k, x, y, z) for k in kids], "MIN")
            return self.var(f"ABS({v}) - {0.5 * float(n['thickness'])!r}")
        if t == "sphere":
            return self.var(f"SQRT({x} * {x} + {y} * {y} + {z} * {z}) - {float(n['radius'])!r}")
        if t == "box":
            h = tree.vec3(n["size"]) / 2
            q = [self.var(f"ABS({c}) - {float(hc)!r}") for c, hc in zip((x, y, z), h)]
            out = self.var(f"SQRT(POS({q[0]}) ** 2 + POS({q[1]}) ** 2 + POS({q[2]}) ** 2)")
            return self.var(f"{out} + MIN(MAX({q[0]}, MAX({q[1]}, {q[2]})), 0.0)")
        if t == "cylinder":
            dr = self.var(f"SQRT({x} * {x} + {y} * {y}) - {float(n['radius'])!r}")
            dz = self.var(f"ABS({z}) - {0.5 * float(n['height'])!r}")
            return self.var(f"MIN(MAX({dr}, {dz}), 0.0) + SQRT(POS({dr}) ** 2 + POS({dz}) ** 2)")
        if t == "cone":
            r1, r2, h = float(n["bottom_radius"]), float(n["top_radius"]), float(n["height"])
            cos_a = h / math.hypot(h, r2 - r1)
            rad = self.var(f"{r1!r} + ({r2 - r1!r}) * ({z} + {h / 2!r}) / {h!r}")
            side = self.var(f"(SQRT({x} * {x} + {y} * {y}) - {rad}) * {cos_a!r}")
            return self.var(f"MAX({side}, ABS({z}) - {h / 2!r})")
        if t == "torus":
            big, small = float(n["major_radius"]), float(n["minor_radius"])
            q = self.var(f"SQRT({x} * {x} + {y} * {y}) - {big!r}")
            return self.var(f"SQRT({q} * {q} + {z} * {z}) - {small!r}")
        if t == "plane":
            nv = np.array(n["normal"], dtype=np.float64)
            nv = nv / np.linalg.norm(nv)
            return self.var(f"{nv[0]!r} * {x} + {nv[1]!r} * {y} + {nv[2]!r} * {z} - {float(n['offset'])!r}")
        if t == "gyroid":
            g = self.var(f"SIN({x}) * COS({y}) + SIN({y}) * COS({z}) + SIN({z}) * COS({x})")
            return self.var(f"ABS({g}) - {float(n['thickness'])!r}")
        if t == "ellipsoid":
            a, b, c = (float(r) for r in n["radii"])
            k = self.var(f"SQRT(({x} / {a!r}) ** 2 + ({y} / {b!r}) ** 2 + ({z} / {c!r}) ** 2)")
            return self.var(f"({k} - 1.0) * {min(a, b, c)!r}")
        if t == "blob":
            terms = []
            for ball in n["balls"]:
                cx, cy, cz = (float(v) for v in ball["center"])
                r2 = f"(({x} - {cx!r}) ** 2 + ({y} - {cy!r}) ** 2 + ({z} - {cz!r}) ** 2)"
                terms.append(f"{float(ball['strength'])!r} * EXP(-{float(ball['sharpness'])!r} * {r2})")
            return self.var(f"{float(n['threshold'])!r} - (" + " + ".join(terms) + ")")
        raise tree.NotExpressible(f"no field for node type '{t}'")


def source(node: dict) -> str:
    g = _Gen()
    out = g.node(node, "x", "y", "z")
    return "def f(x, y, z):\n" + "\n".join(g.lines) + f"\n    return {out}\n"


def compile_field(node: dict, vector: bool):
    """f(x, y, z) of the subtree: over numpy arrays when `vector`, else over floats."""
    ns = dict(VECTOR if vector else SCALAR)
    exec(compile(source(node), "<field>", "exec"), ns)
    return ns["f"]
