"""Meshes of single leaf primitives in their own frame, as manifold3d Manifolds: manifold3d's
primitives (sphere, cube, cylinder, revolve, extrude, hull) where it has them, otherwise
triangle meshes built here from the format's definitions (height fields, tubes, lofts, ruled
solids, polyhedra, mesh files). Curved surfaces get `segments` segments per full turn; their
largest deviation from the exact surface is reported by `sagitta`.
"""
import math
from pathlib import Path

import manifold3d as mf
import numpy as np

from . import curves, meshio, subdivision, tree
from .platonic import platonic_vertices as unit_platonic_vertices
from .tree import NotExpressible


def from_arrays(verts: np.ndarray, faces: np.ndarray) -> mf.Manifold:
    """A Manifold from an indexed mesh, turned outward-facing if its volume came out negative."""
    verts = np.ascontiguousarray(verts, dtype=np.float64)
    faces = np.ascontiguousarray(faces, dtype=np.uint64)
    p = verts[faces.astype(np.int64)]
    if np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() < 0:
        faces = np.ascontiguousarray(faces[:, ::-1])
    m = mf.Manifold(mf.Mesh64(vert_properties=verts, tri_verts=faces))
    if m.status() != mf.Error.NoError or m.is_empty():
        raise RuntimeError(f"leaf mesh rejected by manifold3d: {m.status()}")
    return m


def to_arrays(m: mf.Manifold):
    mesh = m.to_mesh64()
    return (np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3],
            np.asarray(mesh.tri_verts, dtype=np.int64))


def sagitta(radius: float, segments: int) -> float:
    """A bound of the distance between a curved primitive of `radius` and its facets: the
    sagitta of an inscribed polygon of half as many segments, 4× the circle's own, which covers
    manifold3d's geodesic spheres (their faces sink up to 2.7× the circle's sagitta)."""
    return radius * (1 - math.cos(2 * math.pi / segments))


# ---- profiles -------------------------------------------------------------------------------

def profile_loops(p: dict, segments: int) -> list:
    """Closed 2D loops of a profile (outer first, then holes), counter-clockwise outer."""
    t = p["type"]
    if t == "circle":
        c = np.array(p.get("center", [0, 0]), dtype=np.float64)
        a = np.linspace(0, 2 * math.pi, segments, endpoint=False)
        return [c + float(p["radius"]) * np.stack([np.cos(a), np.sin(a)], axis=1)]
    if t == "rectangle":
        s = p["size"]
        w, h = (s, s) if isinstance(s, (int, float)) else s
        c = np.array(p.get("center", [0, 0]), dtype=np.float64)
        return [c + np.array([[-w / 2, -h / 2], [w / 2, -h / 2], [w / 2, h / 2], [-w / 2, h / 2]])]
    if t == "polygon":
        return [np.array(p["points"], dtype=np.float64)] + [np.array(h, dtype=np.float64) for h in p.get("holes", [])]
    raise NotExpressible(f"profile type '{t}'")


def subdivide(loop: np.ndarray, max_edge: float) -> np.ndarray:
    """The loop with points inserted so that no edge is longer than max_edge."""
    out = []
    for a, b in zip(loop, np.roll(loop, -1, axis=0)):
        k = max(int(math.ceil(np.linalg.norm(b - a) / max_edge)), 1)
        out.extend(a + (b - a) * (i / k) for i in range(k))
    return np.array(out)


def cross_section(p: dict, segments: int, max_edge: float = None) -> mf.CrossSection:
    loops = profile_loops(p, segments)
    if max_edge:
        loops = [subdivide(l, max_edge) for l in loops]
    return mf.CrossSection([np.ascontiguousarray(l) for l in loops], mf.FillRule.EvenOdd)


def twisted_extrusion_steps(n: dict, segments: int):
    """Divisions along z and the longest profile edge for a twisted extrusion. Both systems that
    extrude (manifold3d, OpenSCAD) join consecutive slices by two triangles per profile edge; on
    a twisted slab that skews a long edge's quad by (twist per slice)·(edge length), a first-order
    error (2.7 % of the volume of fixtures/examples/twisted_frame.json at 21 slices): so long
    edges are split and slices are dense."""
    twist = abs(float(n.get("twist", 0)))
    if not twist:
        return 0, None
    loops = profile_loops(n["profile"], segments)
    radius = max(float(np.max(np.linalg.norm(l, axis=1))) for l in loops)
    return max(int(twist / 360 * 4 * segments), 1), 2 * math.pi * radius / segments


def signed_area(loop: np.ndarray) -> float:
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


# ---- meshes built here ----------------------------------------------------------------------

def _rings_mesh(rings: list, cap_bottom: bool, cap_top: bool):
    """Closed mesh through rings of equal length (each a closed loop, counter-clockwise seen
    along the stacking direction), rings of one point as apexes, planar caps triangulated by
    manifold3d.triangulate in the plane of the ring's first two axes."""
    verts, faces, index = [], [], []
    for r in rings:
        index.append(list(range(len(verts), len(verts) + len(r))))
        verts.extend(r.tolist())
    for k in range(len(rings) - 1):
        a, b = index[k], index[k + 1]
        if len(a) == 1:
            n = len(b)
            faces += [[a[0], b[(i + 1) % n], b[i]] for i in range(n)]
        elif len(b) == 1:
            n = len(a)
            faces += [[a[i], a[(i + 1) % n], b[0]] for i in range(n)]
        else:
            n = len(a)
            for i in range(n):
                j = (i + 1) % n
                faces += [[a[i], a[j], b[j]], [a[i], b[j], b[i]]]
    for ring, idx, top in ((rings[0], index[0], False), (rings[-1], index[-1], True)):
        if len(idx) < 3 or not (cap_top if top else cap_bottom):
            continue
        tris = mf.triangulate([np.ascontiguousarray(ring[:, :2])])
        for t in np.asarray(tris):
            tri = [idx[i] for i in t]
            faces.append(tri if top else tri[::-1])
    return np.array(verts), np.array(faces)


def heightfield(n: dict, samples: int):
    if "bezier" not in n:
        raise NotExpressible("height field from samples or PNG (only Bezier patches are rebuilt)")
    z = np.array(n["bezier"], dtype=np.float64)  # rows j along y, columns i along x
    (x0, y0), (x1, y1), base = n["min"], n["max"], float(n["base"])
    u = np.linspace(0, 1, samples + 1)
    bu = np.stack([math.comb(z.shape[1] - 1, i) * u ** i * (1 - u) ** (z.shape[1] - 1 - i) for i in range(z.shape[1])])
    bv = np.stack([math.comb(z.shape[0] - 1, j) * u ** j * (1 - u) ** (z.shape[0] - 1 - j) for j in range(z.shape[0])])
    h = bv.T @ z @ bu  # h[jv, iu]
    xs, ys = x0 + (x1 - x0) * u, y0 + (y1 - y0) * u
    m = samples + 1
    X, Y = np.meshgrid(xs, ys)  # [j, i]
    top = np.stack([X, Y, h], axis=-1).reshape(-1, 3)
    bot = np.stack([X, Y, np.full_like(h, base)], axis=-1).reshape(-1, 3)
    verts = np.vstack([top, bot])
    idx = np.arange(m * m).reshape(m, m)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[:-1, 1:].ravel(), idx[1:, 1:].ravel(), idx[1:, :-1].ravel()
    faces = [np.stack([a, b, c], 1), np.stack([a, c, d], 1)]
    off = m * m
    faces += [np.stack([a, c, b], 1) + off, np.stack([a, d, c], 1) + off]
    # side walls along the boundary loop (counter-clockwise seen from above)
    loop = np.concatenate([idx[0, :-1], idx[:-1, -1], idx[-1, :0:-1], idx[:0:-1, 0]])
    nxt = np.roll(loop, -1)
    faces += [np.stack([loop + off, nxt + off, nxt], 1), np.stack([loop + off, nxt, loop], 1)]
    return verts, np.vstack(faces)


def tube(n: dict, segments: int, samples: int):
    prof = n["profile"]
    if prof["type"] != "circle" or any(prof.get("center", [0, 0])):
        raise NotExpressible("sweep of a profile other than a centred circle")
    pos_f, der_f = curves.curve(n["path"])
    t = np.linspace(0, 1, samples + 1)
    pos, tan = pos_f(t), der_f(t)
    tan /= np.linalg.norm(tan, axis=1, keepdims=True)
    nor = curves.rmf(pos, tan)
    bin_ = np.cross(tan, nor)
    a = np.linspace(0, 2 * math.pi, segments, endpoint=False)
    r = float(prof["radius"])
    rings = [p + r * (np.cos(a)[:, None] * nn + np.sin(a)[:, None] * bb) for p, nn, bb in zip(pos, nor, bin_)]
    verts, faces = _rings_mesh(rings, cap_bottom=False, cap_top=False)
    # flat caps: a centre vertex fanned to each end ring
    verts = np.vstack([verts, pos[0], pos[-1]])
    c0, c1 = len(verts) - 2, len(verts) - 1
    first, last = np.arange(segments), np.arange(segments) + segments * samples
    caps = [[c0, first[(i + 1) % segments], first[i]] for i in range(segments)]
    caps += [[c1, last[i], last[(i + 1) % segments]] for i in range(segments)]
    return verts, np.vstack([faces, np.array(caps)])


def loft(n: dict, segments: int, layers: int = 16):
    lb, lt = profile_loops(n["bottom"], segments), profile_loops(n["top"], segments)
    if len(lb) != 1 or len(lt) != 1 or len(lb[0]) != len(lt[0]):
        raise NotExpressible("loft with holes or different corner counts")
    b, t = lb[0], lt[0]
    if signed_area(b) < 0:
        b, t = b[::-1], t[::-1]
    h = float(n["height"])
    rings = []
    for k in range(layers + 1):
        v = k / layers
        ring = (1 - v) * b + v * t
        rings.append(np.hstack([ring, np.full((len(ring), 1), -h / 2 + v * h)]))
    return _rings_mesh(rings, True, True)


def _closed_curve_samples(c: dict, samples: int) -> np.ndarray:
    pts = np.array(c["points"], dtype=np.float64)
    if np.all(pts == pts[0]):
        return pts[:1]
    pos, _ = curves.curve(c)
    return pos(np.linspace(0, 1, samples, endpoint=False))


def ruled(n: dict, samples: int, layers: int = 8):
    b = _closed_curve_samples(n["bottom"], samples)
    t = _closed_curve_samples(n["top"], samples)
    if len(b) > 1 and len(t) > 1 and len(b) != len(t):
        raise NotExpressible("ruled solid between curves sampled differently")
    loop = t if len(t) > 1 else b
    flip = signed_area(loop[:, :2]) < 0
    if flip:
        b, t = b[::-1], t[::-1]
    if b[0, 2] > t[0, 2]:
        b, t = t, b
    rings = []
    for k in range(layers + 1):
        v = k / layers
        if len(b) == 1 and k == 0:
            rings.append(b)
        elif len(t) == 1 and k == layers:
            rings.append(t)
        else:
            bb = b if len(b) > 1 else np.repeat(b, len(t), 0)
            tt = t if len(t) > 1 else np.repeat(t, len(b), 0)
            rings.append((1 - v) * bb + v * tt)
    return _rings_mesh(rings, True, True)


def polyhedron(n: dict):
    verts = np.array(n["vertices"], dtype=np.float64)
    tris = [[f[0], f[k], f[k + 1]] for f in n["faces"] for k in range(1, len(f) - 1)]
    return verts, np.array(tris)


def platonic_vertices(kind: str) -> np.ndarray:
    """Unit-circumradius vertices (xcheck.platonic); a kind nothing here builds is not expressible."""
    try:
        return unit_platonic_vertices(kind)
    except ValueError as e:
        raise NotExpressible(str(e)) from None


def platonic(n: dict) -> mf.Manifold:
    v = platonic_vertices(n["solid"])
    if "circumradius" in n:
        r = float(n["circumradius"])
    else:
        d = np.linalg.norm(v[:, None] - v[None], axis=2)
        r = float(n["edge"]) / d[d > 1e-9].min()
    return mf.Manifold.hull_points(np.ascontiguousarray(v * r))


def _bounded(solid: mf.Manifold, bounds) -> mf.Manifold:
    lo, hi = np.array(bounds[0], dtype=np.float64), np.array(bounds[1], dtype=np.float64)
    box = mf.Manifold.cube(hi - lo).translate(lo)
    return solid ^ box


def _revolved_quadric(radius_of_z, z0: float, z1: float, segments: int, samples: int) -> mf.Manifold:
    z = np.linspace(z0, z1, samples + 1)
    r = radius_of_z(z)
    keep = r > 0
    pts = [[0.0, z[keep][0]]] + [[ri, zi] for ri, zi in zip(r[keep], z[keep])] + [[0.0, z[keep][-1]]]
    return mf.Manifold.revolve(mf.CrossSection([np.array(pts)]), segments)


def quadric(n: dict, segments: int, samples: int) -> mf.Manifold:
    t = n["type"]
    if t == "ellipsoid":
        return mf.Manifold.sphere(1.0, segments).scale(list(map(float, n["radii"])))
    bounds = np.array(n["bounds"], dtype=np.float64)
    z0, z1 = bounds[0, 2] - 0.01, bounds[1, 2] + 0.01
    if t == "elliptic_cylinder":
        a, b = map(float, n["radii"])
        core = mf.Manifold.cylinder(z1 - z0, 1.0, 1.0, segments).translate([0, 0, z0])
        return _bounded(core.scale([a, b, 1.0]), bounds)
    if t == "elliptic_paraboloid":
        a, b = map(float, n["radii"])
        z0 = max(z0, 0.0)
        # z >= rho^2: sample rho uniformly (z = rho^2 is steep in rho near the apex)
        rho = np.linspace(0, math.sqrt(z1), samples + 1)
        pts = [[0.0, z1]] + [[r, r * r] for r in rho]
        pts = np.array(pts)
        pts = pts[(pts[:, 1] >= 0)]
        core = mf.Manifold.revolve(mf.CrossSection([pts[::-1].copy()]), segments)
        if core.volume() <= 0:
            core = mf.Manifold.revolve(mf.CrossSection([pts.copy()]), segments)
        return _bounded(core.scale([a, b, 1.0]), bounds)
    if t == "hyperboloid_one_sheet":
        a, b, c = map(float, n["radii"])
        core = _revolved_quadric(lambda z: np.sqrt(1 + (z / c) ** 2), z0, z1, segments, samples)
        return _bounded(core.scale([a, b, 1.0]), bounds)
    raise NotExpressible(f"quadric '{t}'")


def polygon_mesh(n: dict, base_dir: Path):
    """Vertices and polygon faces of a subdivide node's child."""
    t = n["type"]
    if t == "platonic":
        v = platonic_vertices(n["solid"])
        if "circumradius" in n:
            r = float(n["circumradius"])
        else:
            d = np.linalg.norm(v[:, None] - v[None], axis=2)
            r = float(n["edge"]) / d[d > 1e-9].min()
        v = v * r
        return v, subdivision.platonic_polygons(v)
    if t == "polyhedron":
        return np.array(n["vertices"], dtype=np.float64), [list(f) for f in n["faces"]]
    if t == "mesh":
        return meshio.read_polygons(Path(base_dir) / n["path"])
    raise NotExpressible(f"subdivision of a '{t}' node")


def subdivided(n: dict, base_dir: Path):
    v, faces = polygon_mesh(n["child"], base_dir)
    return subdivision.subdivide(v, faces, n["scheme"], n["levels"])


# ---- the dispatcher ------------------------------------------------------------------------

def leaf(n: dict, base_dir: Path, segments: int, big: float, detail: float = 1.0) -> mf.Manifold:
    """The Manifold of one leaf node in its own frame. `big`: side of the box standing in for a
    half-space (larger than the case's domain); `detail` scales the samples along profiles,
    paths and height fields (OpenSCAD's CGAL is slow on large polyhedra)."""
    t = n["type"]
    s = segments
    k = lambda m: max(16, int(m * s * detail))
    if t == "sphere":
        return mf.Manifold.sphere(float(n["radius"]), s)
    if t == "box":
        return mf.Manifold.cube(tree.vec3(n["size"]), center=True)
    if t == "cylinder":
        return mf.Manifold.cylinder(float(n["height"]), float(n["radius"]), float(n["radius"]), s, center=True)
    if t == "cone":
        return mf.Manifold.cylinder(float(n["height"]), float(n["bottom_radius"]), float(n["top_radius"]), s, center=True)
    if t == "torus":
        cs = mf.CrossSection.circle(float(n["minor_radius"]), s).translate([float(n["major_radius"]), 0])
        return mf.Manifold.revolve(cs, s)
    if t == "plane":
        nv = np.array(n["normal"], dtype=np.float64)
        nv /= np.linalg.norm(nv)
        box = mf.Manifold.cube([big, big, big], center=True).translate([0, 0, float(n["offset"]) - big / 2])
        # rotate +z onto the normal
        z = np.array([0, 0, 1.0])
        axis = np.cross(z, nv)
        if np.linalg.norm(axis) < 1e-12:
            rot = np.eye(3) if nv[2] > 0 else np.diag([1.0, -1.0, -1.0])
        else:
            rot = tree.rotation(axis, math.degrees(math.acos(np.clip(nv @ z, -1, 1))))
        return box.transform(np.hstack([rot, np.zeros((3, 1))]))
    if t == "platonic":
        return platonic(n)
    if t == "polyhedron":
        return from_arrays(*polyhedron(n))
    if t == "mesh":
        return from_arrays(*meshio.read_mesh(Path(base_dir) / n["path"]))
    if t == "prism":
        cs = mf.CrossSection([np.array(n["polygon"], dtype=np.float64)] +
                             [np.array(h, dtype=np.float64) for h in n.get("holes", [])], mf.FillRule.EvenOdd)
        d = np.array(n["direction"], dtype=np.float64)
        shear = np.array([[1, 0, d[0], 0], [0, 1, d[1], 0], [0, 0, d[2], 0]], dtype=np.float64)
        return mf.Manifold.extrude(cs, 1.0).transform(shear)
    if t in ("ellipsoid", "elliptic_cylinder", "elliptic_paraboloid", "hyperboloid_one_sheet"):
        return quadric(n, s, k(4))
    if t == "heightfield":
        return from_arrays(*heightfield(n, k(2)))
    if t == "extrude":
        h = float(n["height"])
        twist = float(n.get("twist", 0))
        sc = float(n.get("scale", 1))
        div, max_edge = twisted_extrusion_steps(n, s)
        m = mf.Manifold.extrude(cross_section(n["profile"], s, max_edge), h, div, twist, (sc, sc))
        return m.translate([0, 0, -h / 2])
    if t == "revolve":
        return mf.Manifold.revolve(cross_section(n["profile"], s), s, float(n.get("angle", 360)))
    if t == "sweep":
        return from_arrays(*tube(n, s, k(4)))
    if t == "subdivide":
        return from_arrays(*subdivided(n, base_dir))
    if t == "loft":
        return from_arrays(*loft(n, s))
    if t == "ruled":
        return from_arrays(*ruled(n, k(4)))
    raise NotExpressible(f"no mesh for node type '{t}'")
