"""OpenVDB (pyopenvdb, Debian's python3-openvdb 10): level-set CSG. Every mesh leaf becomes a
narrow-band level set (`FloatGrid.createLevelSetFromPolygons` of its leaf mesh, placed in the
world); subtrees only a field expresses are sampled densely (numpy, normalised by the gradient
length so they read as distances near the surface); Booleans are min / max / max(a, −b) of the
level sets (what `grid.combine(other, min)` does, done on dense copies of the grids so that
hundreds of operands stay fast); the result goes back into a FloatGrid (`copyFromArray`) and
is meshed by `convertToPolygons` (quads, wound inward: flipped here, and split into triangles).
Voxel size: `openvdb_voxel` cells of solidkit (default 1).
"""
import time

import numpy as np
import pyopenvdb as vdb

from . import bounds, field, leaves, tree

HALF_WIDTH = 3.0


class Builder:
    def __init__(self, ctx):
        self.ctx = ctx
        self.vs = ctx.cell * float(ctx.param("openvdb_voxel", 1.0))
        self.segments = int(ctx.param("openvdb_segments", 128))
        self.bg = HALF_WIDTH * self.vs
        pad = 3 * self.vs
        self.i0 = np.floor((ctx.box[0] - pad) / self.vs).astype(int)
        i1 = np.ceil((ctx.box[1] + pad) / self.vs).astype(int)
        self.shape = tuple(int(d) for d in (i1 - self.i0 + 1))
        self.xform = vdb.createLinearTransform(voxelSize=self.vs)
        c = (ctx.box[0] + ctx.box[1]) / 2
        self.big = 2 * (float(np.linalg.norm(c)) + ctx.diagonal) + 1.0
        self.fields = 0

    def coords(self):
        axes = [(self.i0[k] + np.arange(self.shape[k])) * self.vs for k in range(3)]
        return np.meshgrid(*axes, indexing="ij")

    def dense(self, part) -> np.ndarray:
        """A part as a full array over the domain (a block is +background outside its box)."""
        if isinstance(part, np.ndarray):
            return part
        sl, blk = part
        out = np.full(self.shape, self.bg, dtype=np.float32)
        out[sl] = blk
        return out

    def build(self, n: dict, world: np.ndarray):
        """The level set of a subtree: a dense array over the domain, or for a mesh leaf a block
        (slices, values) outside which it is +background (hundreds of small leaves stay cheap)."""
        t = n["type"]
        if tree.as_field(n):
            return self.field(n, world)
        if t in tree.FIELD_ONLY:
            raise tree.NotExpressible(f"'{t}' over nodes with no field here")
        kids = tree.children(n)
        if t in tree.TRANSFORMS:
            return self.build(kids[0], world @ tree.matrix(n))
        if t in tree.BOOLEANS:
            acc = self.dense(self.build(kids[0], world)).copy()
            for k in kids[1:]:
                part = self.build(k, world)
                if isinstance(part, np.ndarray):
                    sl, blk = (slice(None),) * 3, part
                else:
                    sl, blk = part
                if t == "union":
                    acc[sl] = np.minimum(acc[sl], blk)
                elif t == "difference":
                    acc[sl] = np.maximum(acc[sl], -blk)
                else:
                    inner = np.maximum(acc[sl], blk)
                    acc[...] = self.bg
                    acc[sl] = inner
            return acc
        if t == "plane":  # an exact distance; a box standing in for it would be huge
            return self.field(n, world)
        m = leaves.leaf(n, self.ctx.base_dir, self.segments, self.big)
        verts, faces = leaves.to_arrays(m)
        verts = verts @ world[:3, :3].T + world[:3, 3]
        grid = vdb.FloatGrid.createLevelSetFromPolygons(
            verts.astype(np.float32), triangles=faces.astype(np.int32), transform=self.xform,
            halfWidth=HALF_WIDTH)
        lo, hi = grid.evalActiveVoxelBoundingBox()
        lo = np.maximum(np.array(lo) - self.i0, 0)
        hi = np.minimum(np.array(hi) - self.i0 + 1, self.shape)
        if np.any(hi <= lo):
            return (slice(0, 0),) * 3, np.zeros((0, 0, 0), dtype=np.float32)
        blk = np.empty(tuple(int(d) for d in hi - lo), dtype=np.float32)
        grid.copyToArray(blk, ijk=tuple(int(i) for i in self.i0 + lo))
        return tuple(slice(int(a), int(b)) for a, b in zip(lo, hi)), blk

    def field(self, n: dict, world: np.ndarray) -> np.ndarray:
        self.fields += 1
        wrapped = n if np.allclose(world, np.eye(4)) else {
            "type": "affine", "matrix": world[:3, :].tolist(), "child": n}
        f = field.compile_field(wrapped, vector=True)
        x, y, z = self.coords()
        v = np.asarray(f(x, y, z), dtype=np.float64)
        g = np.gradient(v, self.vs)
        norm = np.sqrt(g[0] ** 2 + g[1] ** 2 + g[2] ** 2)
        v = v / np.maximum(norm, 1e-6)
        return np.clip(v, -self.bg, self.bg).astype(np.float32)


def build(ctx) -> dict:
    b = Builder(ctx)
    start = time.time()
    dense = b.dense(b.build(ctx.root, np.eye(4)))
    grid = vdb.FloatGrid(b.bg)
    grid.transform = b.xform
    grid.gridClass = vdb.GridClass.LEVEL_SET
    grid.copyFromArray(np.ascontiguousarray(dense), ijk=tuple(int(i) for i in b.i0))
    points, tris, quads = grid.convertToPolygons(0.0, 0.0)
    points = np.asarray(points, dtype=np.float64)
    tris = np.asarray(tris, dtype=np.int64).reshape(-1, 3)
    quads = np.asarray(quads, dtype=np.int64).reshape(-1, 4)
    faces = np.vstack([tris, quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])[:, ::-1]  # flip: VDB winds inward
    return {
        "verts": points, "faces": faces, "time_s": time.time() - start,
        "method": "level-set CSG" + (" with sampled fields" if b.fields else "") + ", convertToPolygons",
        "grid": b.vs, "facet_error": leaves.sagitta(bounds.curved_radius(ctx.root, ctx.base_dir), b.segments),
        "own": {}, "settings": {"voxel": b.vs, "segments": b.segments, "half_width": HALF_WIDTH,
                                "grid_shape": list(b.shape)},
    }
