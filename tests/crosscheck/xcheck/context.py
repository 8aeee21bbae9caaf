"""What a builder needs to know about a case: its tree, where relative paths start, the world
box (computed independently of solidkit), the solidkit cell size, and the case's parameters."""
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import bounds, paths, tree


@dataclass
class Context:
    name: str
    source: Path          # the case's input file (.json, .rhai, .csg)
    root: dict            # its JSON tree
    base_dir: Path        # folder that relative paths in the tree start from
    resolution: int       # solidkit cells along the longest side
    params: dict = field(default_factory=dict)
    box: tuple = None     # world box of the solid (lo, hi)

    @property
    def longest(self) -> float:
        return float(np.max(self.box[1] - self.box[0]))

    @property
    def diagonal(self) -> float:
        return float(np.linalg.norm(self.box[1] - self.box[0]))

    @property
    def cell(self) -> float:
        """solidkit's cell: the longest side of the solid's box over N (the grid then adds one
        padding cell at each end, which does not change the cell)."""
        return self.longest / self.resolution

    def param(self, key: str, default):
        return self.params.get(key, default)


def make(case: dict, work: Path, box: tuple = None) -> Context:
    """The context of a case; its world box from `box` when given (solidkit's own run uses its
    report's bbox), else computed here independently (bounds.py) for the references."""
    source = paths.ROOT / case["source"]
    root = tree.load_tree(source, work) if box is None else {}
    ctx = Context(name=case["name"], source=source, root=root, base_dir=source.parent,
                  resolution=int(case["resolution"]), params=case.get("params", {}))
    if box is None:
        box = bounds.bbox(root, ctx.base_dir)
    if box is None:
        raise ValueError(f"{case['name']}: unbounded solid")
    ctx.box = (np.asarray(box[0], dtype=np.float64), np.asarray(box[1], dtype=np.float64))
    return ctx
