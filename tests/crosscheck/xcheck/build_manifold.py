"""manifold3d: exact mesh Booleans of its primitives (and of the leaf meshes of leaves.py), and
`Manifold.level_set` for the subtrees only a field expresses (gyroid, blobs, smooth Booleans,
offset, shell). level_set is sign-reversed (positive inside) and calls back a scalar Python
function, so its grid step (`manifold_edge` cells of solidkit, default 1.5) stays modest. It
runs in a subprocess (the worker): manifold3d 3.5.4 segfaults in level_set on two-valued fields.
"""
import time

import manifold3d as mf
import numpy as np

from . import bounds, field, leaves, tree


class Builder:
    def __init__(self, ctx):
        self.ctx = ctx
        self.segments = int(ctx.param("manifold_segments", 256))
        self.edge = ctx.cell * float(ctx.param("manifold_edge", 1.5))
        self.level_sets = 0
        c = (ctx.box[0] + ctx.box[1]) / 2
        self.big = 4 * (float(np.linalg.norm(c)) + ctx.diagonal) + 1.0

    def build(self, n: dict, world: np.ndarray) -> mf.Manifold:
        t = n["type"]
        if tree.as_field(n):
            return self.level_set(n, world)
        if t in tree.FIELD_ONLY:
            raise tree.NotExpressible(f"'{t}' over nodes with no field here")
        kids = tree.children(n)
        if t in tree.TRANSFORMS:
            return self.build(kids[0], world @ tree.matrix(n))
        if t in tree.BOOLEANS:
            parts = [self.build(k, world) for k in kids]
            if t == "union":
                return mf.Manifold.batch_boolean(parts, mf.OpType.Add)
            if t == "intersection":
                return mf.Manifold.batch_boolean(parts, mf.OpType.Intersect)
            if len(parts) == 1:
                return parts[0]
            return parts[0] - mf.Manifold.batch_boolean(parts[1:], mf.OpType.Add)
        leaf = leaves.leaf(n, self.ctx.base_dir, self.segments, self.big)
        return leaf.transform(np.ascontiguousarray(world[:3, :]))

    def level_set(self, n: dict, world: np.ndarray) -> mf.Manifold:
        wrapped = n if np.allclose(world, np.eye(4)) else {
            "type": "affine", "matrix": world[:3, :].tolist(), "child": n}
        box = bounds.intersection([bounds.bbox(wrapped, self.ctx.base_dir), self.ctx.box])
        lo, hi = box[0] - 2 * self.edge, box[1] + 2 * self.edge
        f = field.compile_field(wrapped, vector=False)
        self.level_sets += 1
        return mf.Manifold.level_set(lambda x, y, z: -f(x, y, z), [*lo, *hi], self.edge)


def build(ctx) -> dict:
    b = Builder(ctx)
    start = time.time()
    m = b.build(ctx.root, np.eye(4))
    if m.status() != mf.Error.NoError:
        raise RuntimeError(f"manifold3d status {m.status()}")
    verts, faces = leaves.to_arrays(m)
    grid = b.edge if b.level_sets else 0.0
    return {
        "verts": verts, "faces": faces, "time_s": time.time() - start,
        "method": ("level_set + " if b.level_sets else "") + "exact Booleans",
        "grid": grid,
        "facet_error": leaves.sagitta(bounds.curved_radius(ctx.root, ctx.base_dir), b.segments),
        "own": {"volume": m.volume(), "area": m.surface_area(), "genus": m.genus(),
                "shells": len(m.decompose())},
        "settings": {"segments": b.segments, "level_set_edge": b.edge if b.level_sets else None},
    }
