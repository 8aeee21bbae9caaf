"""Reading and writing triangle meshes as numpy arrays (vertices float64 [n, 3], faces int64
[m, 3]). Readers: binary and ASCII STL (vertices welded by exact coordinates, as STL repeats them
per facet), OFF and OBJ (polygons fan-triangulated), the binary PLY written here, and the
polygon faces of OBJ and OFF files (for subdivision). Writers: binary PLY with double vertices
(indexed: nothing to weld, nothing lost) and binary STL.
"""
import os
import struct
from pathlib import Path

import numpy as np


def weld(corners: np.ndarray):
    """Indexed mesh from per-corner positions [m, 3, 3]: equal coordinates become one vertex."""
    flat = np.ascontiguousarray(corners.reshape(-1, 3))
    flat = flat + 0.0  # -0.0 and 0.0 are the same point
    keys = flat.view(np.dtype((np.void, flat.dtype.itemsize * 3))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    return flat[first].astype(np.float64), inverse.reshape(-1, 3).astype(np.int64)


def read_stl(path) -> tuple:
    data = Path(path).read_bytes()
    if len(data) >= 84:
        (n,) = struct.unpack_from("<I", data, 80)
        if 84 + 50 * n == len(data):
            rec = np.frombuffer(data, dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)),
                                                      ("a", "<u2")]), count=n, offset=84)
            return weld(rec["v"])
    text = data.decode("ascii", "replace").split()
    coords = [text[i + 1:i + 4] for i, w in enumerate(text) if w == "vertex"]
    corners = np.array(coords, dtype=np.float64).reshape(-1, 3, 3)
    return weld(corners)


def _triangulate(polys):
    tris = []
    for p in polys:
        for k in range(1, len(p) - 1):
            tris.append((p[0], p[k], p[k + 1]))
    return np.array(tris, dtype=np.int64).reshape(-1, 3)


def read_off(path) -> tuple:
    """An OFF file: one vertex per line, one face per line (its corner count, its corners and
    optionally a colour, which is ignored)."""
    lines = []
    for line in Path(path).read_text().splitlines():
        words = line.split("#", 1)[0].split()
        if words:
            lines.append(words)
    if not lines or not lines[0][0].startswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    head = lines[0][0][3:]
    rest = ([head] if head else []) + lines[0][1:]
    pos = 1
    if not rest:  # the counts on their own line, as usual
        rest, pos = lines[1], 2
    nv, nf = int(rest[0]), int(rest[1])
    verts = np.array([w[:3] for w in lines[pos:pos + nv]], dtype=np.float64).reshape(nv, 3)
    polys = []
    for words in lines[pos + nv:pos + nv + nf]:
        k = int(words[0])
        polys.append([int(w) for w in words[1:1 + k]])
    if all(len(p) == 3 for p in polys):
        return verts, np.array(polys, dtype=np.int64).reshape(-1, 3)
    return verts, _triangulate(polys)


def read_obj(path) -> tuple:
    verts, polys = [], []
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            idx = [int(p.split("/")[0]) for p in parts[1:]]
            polys.append([i - 1 if i > 0 else len(verts) + i for i in idx])
    return np.array(verts, dtype=np.float64), _triangulate(polys)


def read_polygons(path) -> tuple:
    """Vertices and polygon faces (lists) of an OBJ or OFF file, faces as written."""
    path = Path(path)
    if path.suffix.lower() == ".obj":
        verts, polys = [], []
        for line in path.read_text().splitlines():
            parts = line.split()
            if parts and parts[0] == "v":
                verts.append([float(x) for x in parts[1:4]])
            elif parts and parts[0] == "f":
                polys.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
        return np.array(verts, dtype=np.float64), polys
    words = " ".join(l.split("#", 1)[0] for l in path.read_text().splitlines()).split()
    nv, nf = int(words[1]), int(words[2])
    verts = np.array(words[4:4 + 3 * nv], dtype=np.float64).reshape(nv, 3)
    pos, polys = 4 + 3 * nv, []
    for _ in range(nf):
        k = int(words[pos])
        polys.append([int(w) for w in words[pos + 1:pos + 1 + k]])
        pos += 1 + k
    return verts, polys


def read_mesh(path) -> tuple:
    ext = Path(path).suffix.lower()
    if ext == ".stl":
        return read_stl(path)
    if ext == ".off":
        return read_off(path)
    if ext == ".obj":
        return read_obj(path)
    if ext == ".ply":
        return read_ply(path)
    raise ValueError(f"{path}: unsupported mesh format {ext}")


def write_stl(path, verts: np.ndarray, faces: np.ndarray) -> None:
    """Binary STL (float32), written atomically."""
    path = Path(path)
    v = np.asarray(verts, dtype=np.float64)[np.asarray(faces)]
    n = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    norm = np.linalg.norm(n, axis=1, keepdims=True)
    n = np.where(norm > 0, n / np.where(norm > 0, norm, 1), 0)
    rec = np.zeros(len(faces), dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]))
    rec["n"], rec["v"] = n, v
    tmp = path.with_suffix(path.suffix + ".tmp")
    with open(tmp, "wb") as f:
        f.write(b"crosscheck".ljust(80, b" "))
        f.write(struct.pack("<I", len(faces)))
        f.write(rec.tobytes())
    os.replace(tmp, path)


def write_ply(path, verts: np.ndarray, faces: np.ndarray) -> None:
    """Binary little-endian PLY, double vertices and int32 triangles (indexed, exact, fast);
    written atomically."""
    path = Path(path)
    verts = np.ascontiguousarray(verts, dtype="<f8")
    rec = np.empty(len(faces), dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]))
    rec["n"], rec["i"] = 3, faces
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(verts)}\n"
              "property double x\nproperty double y\nproperty double z\n"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    tmp = path.with_suffix(path.suffix + ".tmp")
    with open(tmp, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(verts.tobytes())
        f.write(rec.tobytes())
    os.replace(tmp, path)


def read_ply(path) -> tuple:
    """The binary PLY files write_ply writes (double x y z, uchar-counted int triangles)."""
    data = Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").split("\n")
    if "format binary_little_endian 1.0" not in header:
        raise ValueError(f"{path}: only the binary PLY files of write_ply are read here")
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    verts = np.frombuffer(data, dtype="<f8", count=3 * nv, offset=end).reshape(nv, 3)
    rec = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]), count=nf, offset=end + 24 * nv)
    if np.any(rec["n"] != 3):
        raise ValueError(f"{path}: not a triangle mesh")
    return verts.astype(np.float64), rec["i"].astype(np.int64)
