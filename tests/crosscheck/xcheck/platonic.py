"""Unit-circumradius vertices of the Platonic solids from the classic coordinates (as the kernel
documents them in kernel/src/polyhedra/platonic.rs): shared by the manifold3d leaves and by
fixtures/crosscheck/make_cases.py. Needs only numpy."""
import numpy as np

PHI = (1 + 5 ** 0.5) / 2
KINDS = ("tetrahedron", "cube", "octahedron", "icosahedron", "dodecahedron")


def platonic_vertices(kind: str) -> np.ndarray:
    """The vertices of `kind` at circumradius 1; ValueError for an unknown kind."""
    if kind == "tetrahedron":
        v = [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]
    elif kind == "cube":
        v = [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    elif kind == "octahedron":
        v = [[s, 0, 0] for s in (-1, 1)] + [[0, s, 0] for s in (-1, 1)] + [[0, 0, s] for s in (-1, 1)]
    elif kind == "icosahedron":
        v = [p for a in (-1, 1) for b in (-PHI, PHI) for p in ([0, a, b], [a, b, 0], [b, 0, a])]
    elif kind == "dodecahedron":
        v = [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
        v += [p for a in (-1 / PHI, 1 / PHI) for b in (-PHI, PHI) for p in ([0, a, b], [a, b, 0], [b, 0, a])]
    else:
        raise ValueError(f"platonic solid '{kind}'")
    v = np.array(v, dtype=np.float64)
    return v / np.linalg.norm(v[0])
