"""solidkit: CSG and implicit solid modeling, numpy arrays in and out.

Build a tree, evaluate its signed field (negative inside), mesh it into a closed oriented
2-manifold, and check, compare or generate meshes::

    import solidkit as sk

    part = (sk.sphere(1) - sk.box(1.2)).translate([1, 0, 0])
    mesh = part.mesh(resolution=128)
    print(mesh.report()["genus"])          # 7
    values = part.eval([[0, 0, 0], [2, 0, 0]])

Every family of the JSON tree format (sweeps, blobs, polyhedra, height fields, patches, ...) is
reachable through :func:`node`; files load with :func:`load` (``.json``, ``.rhai``, ``.csg``).
Errors are :class:`SolidkitError` subclasses carrying the command line's messages.
"""

from __future__ import annotations

import json as _json
from typing import Any

from ._solidkit import (
    Curve,
    LoadError,
    Mesh,
    MeshIOError,
    MeshingError,
    Solid,
    SolidkitError,
    __version__,
    box,
    check,
    compare,
    cone,
    cube,
    cuboid,
    curve_from_json,
    cylinder,
    difference,
    from_json,
    gen,
    gyroid,
    intersection,
    load,
    plane,
    read,
    smooth_difference,
    smooth_intersection,
    smooth_union,
    sphere,
    torus,
    union,
)

__all__ = [
    "Curve",
    "LoadError",
    "Mesh",
    "MeshIOError",
    "MeshingError",
    "Solid",
    "SolidkitError",
    "__version__",
    "box",
    "check",
    "compare",
    "cone",
    "cube",
    "curve",
    "cuboid",
    "cylinder",
    "difference",
    "from_json",
    "gen",
    "gyroid",
    "intersection",
    "load",
    "node",
    "plane",
    "read",
    "smooth_difference",
    "smooth_intersection",
    "smooth_union",
    "sphere",
    "torus",
    "union",
]


def _embed(value: Any, depth: int = 0) -> Any:
    """``value`` with every Solid replaced by its JSON node (lists, tuples and dicts walked)."""
    if depth > 64:
        raise ValueError("node: values nested deeper than 64")
    if isinstance(value, Solid):
        return _json.loads(value.to_json())["root"]
    if isinstance(value, dict):
        return {str(k): _embed(v, depth + 1) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_embed(v, depth + 1) for v in value]
    if hasattr(value, "tolist"):  # numpy arrays and scalars
        return value.tolist()
    return value


def node(kind: "str | dict[str, Any]", /, **params: Any) -> Solid:
    """Any node of the JSON tree format, e.g. every family without a function of its own.

    ``node("extrude", profile={"type": "circle", "radius": 1}, height=2)`` or the same as one
    dict with a ``"type"`` key. Solids may stand wherever the format expects a node
    (``child=``, ``children=[...]``). The keys are those of ``docs/json-format.md``; errors name the
    offending key.
    """
    if isinstance(kind, dict):
        description = dict(kind)
        description.update(params)
    else:
        description = {"type": kind, **params}
    return from_json(_json.dumps(_embed(description), allow_nan=False), name="node")


def curve(kind: "str | dict[str, Any]", /, **params: Any) -> Curve:
    """A curve of the JSON format (``docs/json-format.md``, "Curves"), to evaluate.

    ``curve("bezier", points=[[0, -1], [1, 2], [5, -1]]).point(0.3)`` is ``(0.87, 0.26, 0.0)``;
    every kind works: ``bezier``, ``hermite``, ``bspline``, ``nurbs``, ``interpolating``,
    ``cubic_through``, ``composite`` (continuity checked) and ``formula``.
    """
    if isinstance(kind, dict):
        description = dict(kind)
        description.update(params)
    else:
        description = {"type": kind, **params}
    return curve_from_json(_json.dumps(description, allow_nan=False))
