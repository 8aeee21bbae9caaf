"""The solidkit JSON tree (docs/json-format.md) as the references see it: loading (other inputs
through `solidkit convert`), the affine map of each transform node, and which subtrees are built
as fields (level sets) rather than as meshes.

Trees here are small fixtures, so walking them by recursion is fine.
"""
import json
import math
import subprocess
from pathlib import Path

import numpy as np

from . import paths

TRANSFORMS = {"translate", "rotate", "scale", "mirror", "affine"}
BOOLEANS = {"union", "intersection", "difference"}
# Nodes only a field can express (no mesh primitive or exact Boolean builds them).
FIELD_ONLY = {"gyroid", "blob", "smooth_union", "smooth_intersection", "smooth_difference",
              "offset", "shell"}
# Nodes field.py can evaluate.
FIELD_LEAVES = {"sphere", "box", "cylinder", "cone", "torus", "plane", "gyroid", "blob",
                "ellipsoid"}
FIELD_NODES = FIELD_LEAVES | BOOLEANS | TRANSFORMS | FIELD_ONLY


class NotExpressible(Exception):
    """The case cannot be built in this system (the message says why)."""


def load_tree(source: Path, work: Path) -> dict:
    """The JSON tree of a case source (.json read as is; .rhai and .csg through solidkit convert)."""
    source = Path(source)
    if source.suffix == ".json":
        doc = json.loads(source.read_text())
    else:
        out = Path(work) / (source.stem + ".tree.json")
        subprocess.run([str(paths.solidkit_bin()), "convert", str(source), "-o", str(out)],
                       check=True, capture_output=True)
        doc = json.loads(out.read_text())
    return doc["root"] if "root" in doc else doc


def children(node: dict) -> list:
    if "children" in node:
        return node["children"]
    if "child" in node:
        return [node["child"]]
    return []


def vec3(x) -> np.ndarray:
    if isinstance(x, (int, float)):
        return np.array([x, x, x], dtype=np.float64)
    return np.array(x, dtype=np.float64)


def rotation(axis, degrees) -> np.ndarray:
    """Right-hand rotation matrix about `axis` by `degrees` (Rodrigues)."""
    k = np.array(axis, dtype=np.float64)
    k = k / np.linalg.norm(k)
    t = math.radians(degrees)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(t) * kx + (1 - math.cos(t)) * kx @ kx


def matrix(node: dict) -> np.ndarray:
    """The 4×4 affine map p' = M p of a transform node."""
    m = np.eye(4)
    t = node["type"]
    if t == "translate":
        m[:3, 3] = node["offset"]
    elif t == "rotate":
        m[:3, :3] = rotation(node["axis"], node["degrees"])
    elif t == "scale":
        m[:3, :3] = np.diag(vec3(node["factor"]))
    elif t == "mirror":
        n = np.array(node["normal"], dtype=np.float64)
        n = n / np.linalg.norm(n)
        m[:3, :3] = np.eye(3) - 2 * np.outer(n, n)
    elif t == "affine":
        m[:3, :] = np.array(node["matrix"], dtype=np.float64)
    else:
        raise ValueError(f"not a transform: {t}")
    return m


def has_field_only(node: dict) -> bool:
    if node["type"] in FIELD_ONLY:
        return True
    return any(has_field_only(c) for c in children(node))


def field_evaluable(node: dict) -> bool:
    if node["type"] not in FIELD_NODES:
        return False
    return all(field_evaluable(c) for c in children(node))


def as_field(node: dict) -> bool:
    """True when this subtree is built as one level set: it contains a field-only node and
    field.py can evaluate all of it (the largest such subtrees are taken, so a gyroid clipped by
    a ball is one level set). A field-only node with an unevaluable child is not expressible."""
    return has_field_only(node) and field_evaluable(node)


def node_types(node: dict) -> set:
    out = {node["type"]}
    for c in children(node):
        out |= node_types(c)
    return out
