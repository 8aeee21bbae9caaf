"""The `subdivide` node rebuilt for the references from the format's documented rules
(docs/json-format.md, the rules in meshing/src/subdivision/*): Catmull-Clark on polygon meshes
and Loop (Loop's original vertex weight) on triangle meshes, closed meshes only, then the quads
split into two triangles. The child's polygon faces: a Platonic solid's faces (coplanar hull
triangles merged), a polyhedron's faces, or an OBJ/OFF file's polygons."""
import math
from collections import defaultdict

import numpy as np

from .tree import NotExpressible


def platonic_polygons(verts: np.ndarray) -> list:
    """The polygon faces of a convex polytope with these vertices, counter-clockwise outside."""
    import manifold3d as mf
    m = mf.Manifold.hull_points(np.ascontiguousarray(verts)).to_mesh64()
    pv = np.asarray(m.vert_properties)[:, :3]
    tri = np.asarray(m.tri_verts)
    faces = {}
    for t in tri:
        n = np.cross(pv[t[1]] - pv[t[0]], pv[t[2]] - pv[t[0]])
        n /= np.linalg.norm(n)
        key = tuple(np.round(n, 6))
        faces.setdefault(key, n)
    out = []
    for n in faces.values():
        d = float(np.max(verts @ n))
        on = [i for i, v in enumerate(verts) if abs(v @ n - d) < 1e-9]
        c = verts[on].mean(axis=0)
        u = verts[on[0]] - c
        u /= np.linalg.norm(u)
        w = np.cross(n, u)
        ang = [math.atan2((verts[i] - c) @ w, (verts[i] - c) @ u) for i in on]
        out.append([on[i] for i in np.argsort(ang)])
    return out


def _edges(faces):
    """Undirected edge -> list of (face index, position) and each face's edge keys."""
    adj = defaultdict(list)
    for fi, f in enumerate(faces):
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            adj[(min(a, b), max(a, b))].append(fi)
    if any(len(v) != 2 for v in adj.values()):
        raise NotExpressible("subdivision of an open or non-manifold mesh")
    return adj


def catmull_clark(verts: np.ndarray, faces: list):
    adj = _edges(faces)
    fp = np.array([verts[f].mean(axis=0) for f in faces])
    eindex = {e: len(verts) + i for i, e in enumerate(adj)}
    ep = np.array([(verts[a] + verts[b] + fp[f1] + fp[f2]) / 4 for (a, b), (f1, f2) in adj.items()])
    vfaces, vedges = defaultdict(list), defaultdict(list)
    for fi, f in enumerate(faces):
        for v in f:
            vfaces[v].append(fi)
    for (a, b) in adj:
        vedges[a].append((a, b))
        vedges[b].append((a, b))
    vp = verts.copy()
    for v in range(len(verts)):
        n = len(vedges[v])
        q = fp[vfaces[v]].mean(axis=0)
        r = np.mean([(verts[a] + verts[b]) / 2 for a, b in vedges[v]], axis=0)
        vp[v] = (q + 2 * r + (n - 3) * verts[v]) / n
    fbase = len(verts) + len(adj)
    new = []
    for fi, f in enumerate(faces):
        k = len(f)
        for i in range(k):
            prev, cur, nxt = f[i - 1], f[i], f[(i + 1) % k]
            new.append([cur, eindex[(min(cur, nxt), max(cur, nxt))], fbase + fi,
                        eindex[(min(prev, cur), max(prev, cur))]])
    return np.vstack([vp, ep, fp]), new


def loop(verts: np.ndarray, faces: list):
    if any(len(f) != 3 for f in faces):
        raise NotExpressible("Loop subdivision of non-triangles")
    adj = _edges(faces)
    eindex = {e: len(verts) + i for i, e in enumerate(adj)}
    ep = []
    for (a, b), (f1, f2) in adj.items():
        c = [v for v in faces[f1] if v not in (a, b)][0]
        d = [v for v in faces[f2] if v not in (a, b)][0]
        ep.append(3 / 8 * (verts[a] + verts[b]) + 1 / 8 * (verts[c] + verts[d]))
    nbrs = defaultdict(set)
    for a, b in adj:
        nbrs[a].add(b)
        nbrs[b].add(a)
    vp = verts.copy()
    for v in range(len(verts)):
        n = len(nbrs[v])
        beta = (5 / 8 - (3 / 8 + 0.25 * math.cos(2 * math.pi / n)) ** 2) / n
        vp[v] = (1 - n * beta) * verts[v] + beta * verts[list(nbrs[v])].sum(axis=0)
    new = []
    for a, b, c in faces:
        ab, bc, ca = (eindex[(min(x, y), max(x, y))] for x, y in ((a, b), (b, c), (c, a)))
        new += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
    return np.vstack([vp, np.array(ep)]), new


def subdivide(verts: np.ndarray, faces: list, scheme: str, levels: int):
    """Triangles (verts, faces) of the subdivided polygon mesh."""
    step = {"catmull-clark": catmull_clark, "loop": loop}.get(scheme)
    if step is None:
        raise NotExpressible(f"subdivision scheme '{scheme}'")
    verts = np.asarray(verts, dtype=np.float64)
    for _ in range(int(levels)):
        verts, faces = step(verts, faces)
    tris = [[f[0], f[k], f[k + 1]] for f in faces for k in range(1, len(f) - 1)]
    return verts, np.array(tris)
