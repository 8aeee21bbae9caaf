"""The reference systems' timed builds of a speed case (speed_cases.py), each by its native path:

- `openvdb-sphere`: `createLevelSetSphere` (narrow band, half width 3 voxels) then
  `convertToPolygons`.
- `openvdb-field`: the tree's field sampled with numpy (xcheck/field.py) on the dense voxel grid
  over the solid's bbox padded by 3 voxels, clipped to the narrow band (±3 voxels, so the rest
  is inactive background), `copyFromArray` into a level-set FloatGrid, then `convertToPolygons`.
  OpenVDB has no expression evaluator: a program samples its own field into a grid.
- `openvdb-csg`: the cross-check harness's level-set CSG (build_openvdb.Builder: one
  `createLevelSetFromPolygons` per box, Booleans as min / max on dense arrays), then
  `copyFromArray` and `convertToPolygons`.
- `manifold3d-level-set`: `Manifold.level_set` of the field with the cell as edge length over the
  bbox padded by 2 cells; its API calls back a Python function once per grid point (the field
  compiled to straight-line float code, negated inside it: positive inside).
- `manifold3d-exact`: the harness's exact Booleans (build_manifold.Builder: `Manifold.cube`
  leaves, `batch_boolean`); no grid. Its Booleans are lazy: the timed part ends with the mesh
  read out (`to_mesh64`).

Each `build` returns the seconds of each phase and the mesh as (verts, faces) triangle arrays
(OpenVDB's inward-wound quads flipped and split after the timing).
"""
import math
from time import perf_counter

import numpy as np

from . import field, paths, speed_cases

HALF_WIDTH = 3.0
SLAB_POINTS = 1 << 20


def _vdb_mesh(points, tris, quads):
    points = np.asarray(points, dtype=np.float64)
    tris = np.asarray(tris, dtype=np.int64).reshape(-1, 3)
    quads = np.asarray(quads, dtype=np.int64).reshape(-1, 4)
    faces = np.vstack([tris, quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])[:, ::-1]
    return points, faces


def _level_set_grid(vdb, values: np.ndarray, i0, voxel: float, background: float):
    grid = vdb.FloatGrid(background)
    grid.transform = vdb.createLinearTransform(voxelSize=voxel)
    grid.gridClass = vdb.GridClass.LEVEL_SET
    grid.copyFromArray(np.ascontiguousarray(values), ijk=tuple(int(i) for i in i0))
    return grid


class OpenVdbSphere:
    method = "createLevelSetSphere + convertToPolygons"

    def __init__(self, case):
        import pyopenvdb as vdb
        self.vdb, self.case = vdb, case

    def build(self):
        t0 = perf_counter()
        grid = self.vdb.createLevelSetSphere(speed_cases.SPHERE_RADIUS, (0.0, 0.0, 0.0),
                                             self.case.cell, HALF_WIDTH)
        t1 = perf_counter()
        out = grid.convertToPolygons(0.0, 0.0)
        t2 = perf_counter()
        return {"level set": t1 - t0, "convertToPolygons": t2 - t1}, out

    mesh = staticmethod(lambda out: _vdb_mesh(*out))


class OpenVdbField:
    method = "numpy samples + copyFromArray + convertToPolygons"

    def __init__(self, case):
        import pyopenvdb as vdb
        self.vdb, self.case = vdb, case
        self.f = field.compile_field(case.tree(), vector=True)
        h = case.cell
        self.bg = HALF_WIDTH * h
        self.i0 = math.floor((-case.half - HALF_WIDTH * h) / h)
        i1 = math.ceil((case.half + HALF_WIDTH * h) / h)
        self.axis = (self.i0 + np.arange(i1 - self.i0 + 1)) * h

    def build(self):
        ax, n = self.axis, len(self.axis)
        t0 = perf_counter()
        values = np.empty((n, n, n), dtype=np.float32)
        step = max(1, SLAB_POINTS // (n * n))
        y, z = ax[None, :, None], ax[None, None, :]
        for a in range(0, n, step):
            v = self.f(ax[a:a + step, None, None], y, z)
            np.clip(v, -self.bg, self.bg, out=values[a:a + step])
        t1 = perf_counter()
        grid = _level_set_grid(self.vdb, values, (self.i0,) * 3, self.case.cell, self.bg)
        t2 = perf_counter()
        out = grid.convertToPolygons(0.0, 0.0)
        t3 = perf_counter()
        return {"sample (numpy)": t1 - t0, "copyFromArray": t2 - t1, "convertToPolygons": t3 - t2}, out

    mesh = staticmethod(lambda out: _vdb_mesh(*out))


def _context(case):
    """The harness's build context of the case's fixture, with the cell set to h."""
    from . import context
    source = paths.ROOT / case.fixture
    ctx = context.Context(name=case.name, source=source, root=case.tree(), base_dir=source.parent,
                          resolution=case.mesh_resolution, box=case.box)
    return ctx


class OpenVdbCsg:
    method = "level-set CSG (harness) + convertToPolygons"

    def __init__(self, case):
        import pyopenvdb as vdb
        from . import build_openvdb
        self.vdb, self.case = vdb, case
        self.ctx = _context(case)
        self.ctx.params["openvdb_voxel"] = case.cell / self.ctx.cell
        self.builder_class = build_openvdb.Builder

    def build(self):
        t0 = perf_counter()
        b = self.builder_class(self.ctx)
        dense = b.dense(b.build(self.ctx.root, np.eye(4)))
        t1 = perf_counter()
        grid = _level_set_grid(self.vdb, dense, b.i0, b.vs, b.bg)
        t2 = perf_counter()
        out = grid.convertToPolygons(0.0, 0.0)
        t3 = perf_counter()
        return {"CSG": t1 - t0, "copyFromArray": t2 - t1, "convertToPolygons": t3 - t2}, out

    mesh = staticmethod(lambda out: _vdb_mesh(*out))


def _manifold_mesh(mesh):
    return (np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3],
            np.asarray(mesh.tri_verts, dtype=np.int64))


class ManifoldLevelSet:
    method = "Manifold.level_set (Python callback per point)"

    def __init__(self, case):
        import manifold3d as mf
        self.mf, self.case = mf, case
        src = field.source(case.tree())
        last = src.rstrip().rsplit("\n", 1)
        src = last[0] + "\n" + last[1].replace("return ", "return -") + "\n"
        ns = dict(field.SCALAR)
        exec(compile(src, "<field>", "exec"), ns)
        self.f = ns["f"]
        pad = case.half + 2 * case.cell
        self.bounds = [-pad] * 3 + [pad] * 3

    def build(self):
        t0 = perf_counter()
        m = self.mf.Manifold.level_set(self.f, self.bounds, self.case.cell)
        mesh = m.to_mesh64()
        t1 = perf_counter()
        if m.status() != self.mf.Error.NoError:
            raise RuntimeError(f"manifold3d status {m.status()}")
        return {"level_set + to_mesh64": t1 - t0}, mesh

    mesh = staticmethod(_manifold_mesh)


class ManifoldExact:
    method = "exact Booleans of Manifold.cube (harness), no grid"

    def __init__(self, case):
        import manifold3d as mf
        from . import build_manifold
        self.mf, self.case = mf, case
        self.ctx = _context(case)
        self.builder_class = build_manifold.Builder

    def build(self):
        t0 = perf_counter()
        m = self.builder_class(self.ctx).build(self.ctx.root, np.eye(4))
        mesh = m.to_mesh64()
        t1 = perf_counter()
        if m.status() != self.mf.Error.NoError:
            raise RuntimeError(f"manifold3d status {m.status()}")
        return {"Booleans + to_mesh64": t1 - t0}, mesh

    mesh = staticmethod(_manifold_mesh)


SYSTEMS = {
    speed_cases.OPENVDB_SPHERE: OpenVdbSphere,
    speed_cases.OPENVDB_FIELD: OpenVdbField,
    speed_cases.OPENVDB_CSG: OpenVdbCsg,
    speed_cases.MANIFOLD_LEVEL_SET: ManifoldLevelSet,
    speed_cases.MANIFOLD_EXACT: ManifoldExact,
}
