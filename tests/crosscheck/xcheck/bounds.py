"""Bounding boxes of JSON subtrees in world coordinates, computed for the references
independently of solidkit: mesh leaves from their leaf meshes, field leaves from their
parameters (gyroid and plane unbounded), Booleans and unary operations by the usual rules.
Used to place level-set grids and to size half-space boxes."""
import math

import numpy as np

from . import leaves, tree

INF = None  # an unbounded box


def _corners(lo, hi):
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def transform_box(box, m: np.ndarray):
    if box is INF:
        return INF
    c = _corners(*box) @ m[:3, :3].T + m[:3, 3]
    return c.min(0), c.max(0)


def grow(box, d: float):
    if box is INF:
        return INF
    return box[0] - d, box[1] + d


def union(boxes):
    if any(b is INF for b in boxes):
        return INF
    return np.min([b[0] for b in boxes], 0), np.max([b[1] for b in boxes], 0)


def intersection(boxes):
    finite = [b for b in boxes if b is not INF]
    if not finite:
        return INF
    return np.max([b[0] for b in finite], 0), np.min([b[1] for b in finite], 0)


def _field_leaf(n: dict):
    t = n["type"]
    if t == "sphere":
        r = float(n["radius"])
        return -np.full(3, r), np.full(3, r)
    if t == "box":
        h = tree.vec3(n["size"]) / 2
        return -h, h
    if t == "cylinder":
        r, h = float(n["radius"]), float(n["height"]) / 2
        return -np.array([r, r, h]), np.array([r, r, h])
    if t == "cone":
        r, h = max(float(n["bottom_radius"]), float(n["top_radius"])), float(n["height"]) / 2
        return -np.array([r, r, h]), np.array([r, r, h])
    if t == "torus":
        a, b = float(n["major_radius"]), float(n["minor_radius"])
        return -np.array([a + b, a + b, b]), np.array([a + b, a + b, b])
    if t == "ellipsoid":
        r = np.array(n["radii"], dtype=np.float64)
        return -r, r
    if t == "blob":
        s = sum(float(b["strength"]) for b in n["balls"] if float(b["strength"]) > 0)
        thr = float(n["threshold"])
        boxes = []
        for b in n["balls"]:
            if float(b["strength"]) <= 0:
                continue
            r = math.sqrt(max(math.log(s / thr), 0.0) / float(b["sharpness"]))
            c = np.array(b["center"], dtype=np.float64)
            boxes.append((c - r, c + r))
        return union(boxes)
    if t in ("gyroid", "plane"):
        return INF
    return None


def bbox(n: dict, base_dir, segments: int = 32):
    """World box of the subtree `n` (INF when unbounded)."""
    t = n["type"]
    kids = tree.children(n)
    if t in tree.TRANSFORMS:
        return transform_box(bbox(kids[0], base_dir, segments), tree.matrix(n))
    if t in ("union", "smooth_union"):
        b = union([bbox(k, base_dir, segments) for k in kids])
        return grow(b, float(n.get("radius", 0)))
    if t in ("intersection", "smooth_intersection"):
        return intersection([bbox(k, base_dir, segments) for k in kids])
    if t in ("difference", "smooth_difference"):
        return bbox(kids[0], base_dir, segments)
    if t == "offset":
        return grow(union([bbox(k, base_dir, segments) for k in kids]), max(float(n["distance"]), 0.0))
    if t == "shell":
        return grow(union([bbox(k, base_dir, segments) for k in kids]), float(n["thickness"]) / 2)
    b = _field_leaf(n)
    if b is not None or t in ("gyroid", "plane"):
        return b
    m = leaves.leaf(n, base_dir, segments, big=1.0)
    lo = m.bounding_box()
    return np.array(lo[:3]), np.array(lo[3:])


CURVED = {"subdivide", "sphere", "cylinder", "cone", "torus", "ellipsoid", "elliptic_cylinder",
          "elliptic_paraboloid", "hyperboloid_one_sheet", "revolve", "sweep", "extrude", "loft",
          "ruled", "heightfield"}


def curved_radius(n: dict, base_dir, scale: float = 1.0) -> float:
    """The largest radius of the curved leaves of a subtree in world units (0 when every leaf
    is flat-faced): what a faceted system's facet error scales with."""
    t = n["type"]
    kids = tree.children(n)
    if t in tree.TRANSFORMS:
        s = float(np.linalg.svd(tree.matrix(n)[:3, :3], compute_uv=False).max())
        return curved_radius(kids[0], base_dir, scale * s)
    if kids:
        return max(curved_radius(k, base_dir, scale) for k in kids)
    if t not in CURVED:
        return 0.0
    if t == "sphere":
        r = float(n["radius"])
    elif t == "cylinder":
        r = float(n["radius"])
    elif t == "cone":
        r = max(float(n["bottom_radius"]), float(n["top_radius"]))
    elif t == "torus":
        r = float(n["major_radius"]) + float(n["minor_radius"])
    elif t in ("extrude", "loft") and all(p.get("type") != "circle" for p in
                                          (n.get("profile", {}), n.get("bottom", {}), n.get("top", {}))) \
            and not float(n.get("twist", 0)):
        return 0.0
    else:
        b = bbox(n, base_dir)
        r = float(np.max(np.abs(np.concatenate(b)))) if b is not INF else 0.0
    return r * scale
