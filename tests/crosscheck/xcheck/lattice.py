"""Random CSG trees of boxes and cylinders on a coarse lattice (issue 13), meshed by solidkit and
built by manifold3d's exact Booleans, compared tree by tree (docs/crosscheck.md, "Lattice
trees").

Every box corner, cylinder cap and cylinder axis lies on the lattice STEP·Z³ inside
[-EXTENT·STEP, EXTENT·STEP]³, so faces coincide often: boxes sharing faces, caps flush with box
faces and with other caps, coaxial cylinders of the same radius (coincident curved sides).
Cylinders run along x, y or z (x and y by exact permutation matrices, `affine`: a rotation by 90°
would move the caps off the lattice by rounding).

What must not happen is a tangency between a round side and anything else, where the exact and
the faceted or sampled geometry legitimately disagree in topology. With one radius RADIUS for all
cylinders (0.3 at STEP 0.5; the 0.7 first considered lies 0.007 from a box edge at distance
0.5·√2) the critical distances are (`tangency_margin` computes them):

- a side against a lattice plane or lattice line parallel to its axis (box faces, box edges,
  caps of perpendicular cylinders): |RADIUS − STEP·√n| over sums of two squares n;
- two parallel sides, axes STEP·√n apart (n ≥ 1): |2·RADIUS − STEP·√n|; coaxial sides coincide
  (wanted); the lines where two sides cross (only at axes STEP apart) against lattice planes and
  against a third parallel side;
- two perpendicular sides whose axes are STEP·k apart (k ≥ 1): |2·RADIUS − STEP·k|, and the
  extremes of their intersection curve against lattice planes. Perpendicular axes that meet
  (k = 0, equal radii: the curve has two singular points, Steinmetz) are not generated: `generate`
  redraws a cylinder whose box touches such a partner's.

The smallest of these is 0.1, 1.56 cells at the coarsest grid (a tree's bounds reach 3.6 with
the radius, over 56 cells; the test asserts at least 1.5), so no tangency hides below the grid.
"""
import itertools
import json
import math
import os
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import manifold3d as mf
import numpy as np

from . import bounds, build_manifold, context, leaves, measure, meshio, paths, tolerance, tree

STEP = 0.5
EXTENT = 3            # lattice indices -EXTENT..EXTENT: coordinates in [-1.5, 1.5]
RADIUS = 0.3
SEGMENTS = 96         # manifold3d's cylinder facets
RESOLUTIONS = (56, 59, 64, 67)  # even and odd: lattice planes on sample points and between them
LEAVES = (2, 6)       # leaves per tree, inclusive
FLAT = 1e-9           # a manifold3d shell of no larger volume is a flat sheet (the solid is empty there)
AXES = "xyz"
# child z -> world axis, as exact permutation matrices (p' = M p)
PERMUTATION = {"x": [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
               "y": [[0, 1, 0], [0, 0, 1], [1, 0, 0]]}


def _two_square_sums(limit: int) -> list:
    return sorted({a * a + b * b for a in range(limit + 1) for b in range(limit + 1)})


def tangency_margin(radius: float = RADIUS, step: float = STEP) -> float:
    """The smallest distance, over the configurations the generator can make, between a round
    side and a position where it would be tangent to something (module docs)."""
    span = 2 * EXTENT + 2
    dists = [step * math.sqrt(n) for n in _two_square_sums(span)]   # transverse axis offsets
    gaps = [abs(radius - d) for d in dists]                         # side vs planes, lines
    gaps += [abs(2 * radius - d) for d in dists if d > 0]           # parallel sides
    gaps += [abs(2 * radius - step * k) for k in range(1, span)]    # perpendicular sides
    planes = [step * k for k in range(-span, span + 1)]
    if 2 * radius > step:
        # two parallel sides with axes one STEP apart cross along lines at (STEP/2, ±h): against
        # lattice planes and against a third side about another lattice axis
        h = math.sqrt(radius ** 2 - (step / 2) ** 2)
        gaps += [abs(c - p) for c in (step / 2, h) for p in planes]
        others = [math.hypot(step / 2 - step * i, h - step * j)
                  for i in range(-span, span) for j in range(-span, span) if (i, j) not in ((0, 0), (1, 0))]
        gaps += [abs(d - radius) for d in others]
        # perpendicular sides with axes one STEP apart: the intersection curve reaches
        # sqrt(r² − (STEP − r)²) from each axis (against lattice planes), and spans
        # [STEP − r, r] along the offset (against lattice planes)
        reach = math.sqrt(max(radius ** 2 - (step - radius) ** 2, 0.0))
        gaps += [abs(c - p) for c in (reach, step - radius, radius) for p in planes]
    return min(gaps)


# ---- trees ---------------------------------------------------------------------------------

def _box_leaf(rng) -> dict:
    lo, hi = [], []
    for _ in range(3):
        size = int(rng.integers(1, 5))
        a = int(rng.integers(-EXTENT, EXTENT - size + 1))
        lo.append(a)
        hi.append(a + size)
    return {"kind": "box", "lo": lo, "hi": hi}


def _cylinder_leaf(rng) -> dict:
    axis = AXES[int(rng.integers(3))]
    k = AXES.index(axis)
    centre = [int(rng.integers(-EXTENT, EXTENT + 1)) for _ in range(3)]
    length = int(rng.integers(1, 6))
    a = int(rng.integers(-EXTENT, EXTENT - length + 1))
    lo, hi = list(centre), list(centre)
    lo[k], hi[k] = a, a + length
    return {"kind": "cylinder", "axis": axis, "lo": lo, "hi": hi}


def _box_of(leaf: dict):
    """World box in lattice units (cylinders widened by their radius)."""
    lo, hi = np.array(leaf["lo"], float), np.array(leaf["hi"], float)
    if leaf["kind"] == "cylinder":
        k = AXES.index(leaf["axis"])
        grow = np.full(3, RADIUS / STEP)
        grow[k] = 0
        lo, hi = lo - grow, hi + grow
    return lo, hi


def _singular_pair(a: dict, b: dict) -> bool:
    """Perpendicular cylinders with meeting axes whose boxes touch (equal radii: the sides meet
    at singular points)."""
    if a["kind"] != "cylinder" or b["kind"] != "cylinder" or a["axis"] == b["axis"]:
        return False
    third = ({0, 1, 2} - {AXES.index(a["axis"]), AXES.index(b["axis"])}).pop()
    if a["lo"][third] != b["lo"][third]:
        return False
    (alo, ahi), (blo, bhi) = _box_of(a), _box_of(b)
    return bool(np.all(alo <= bhi) and np.all(blo <= ahi))


def _leaf_json(leaf: dict) -> dict:
    lo, hi = np.array(leaf["lo"]) * STEP, np.array(leaf["hi"]) * STEP
    centre = ((lo + hi) / 2).tolist()
    if leaf["kind"] == "box":
        node = {"type": "box", "size": (hi - lo).tolist()}
        return {"type": "translate", "offset": centre, "child": node}
    k = AXES.index(leaf["axis"])
    node = {"type": "cylinder", "radius": RADIUS, "height": float(hi[k] - lo[k])}
    if leaf["axis"] == "z":
        return {"type": "translate", "offset": centre, "child": node}
    rows = [row + [c] for row, c in zip(PERMUTATION[leaf["axis"]], centre)]
    return {"type": "affine", "matrix": rows, "child": node}


def _combine(nodes: list, rng) -> dict:
    if len(nodes) == 1:
        return nodes[0]
    op = ["union", "difference", "intersection"][int(rng.integers(3))]
    # two children, or three for a union or an intersection now and then
    parts = 3 if len(nodes) >= 3 and op != "difference" and rng.random() < 0.3 else 2
    cuts = sorted(rng.choice(np.arange(1, len(nodes)), size=parts - 1, replace=False).tolist())
    groups = [nodes[i:j] for i, j in zip([0] + cuts, cuts + [len(nodes)])]
    return {"type": op, "children": [_combine(g, rng) for g in groups]}


def generate(seed: int, index: int) -> dict:
    """Tree number `index` of the stream `seed`: {"root", "resolution", "leaves"} (deterministic)."""
    rng = np.random.default_rng([seed, index])
    count = int(rng.integers(LEAVES[0], LEAVES[1] + 1))
    chosen = []
    while len(chosen) < count:
        leaf = _cylinder_leaf(rng) if rng.random() < 0.45 else _box_leaf(rng)
        if not any(_singular_pair(leaf, other) for other in chosen):
            chosen.append(leaf)
    root = _combine([_leaf_json(l) for l in chosen], rng)
    return {"root": root, "resolution": int(rng.choice(RESOLUTIONS)), "leaves": chosen}


# ---- the two systems -----------------------------------------------------------------------

def make_context(root: dict, resolution: int) -> context.Context:
    """The harness's context of a tree: its box by the rules solidkit bounds a tree with
    (xcheck/bounds.py; an empty intersection keeps its inverted box, as in solidkit), so
    `ctx.cell` is solidkit's cell (checked against its report's cell counts)."""
    box = bounds.bbox(root, paths.ROOT)
    return context.Context(name="lattice", source=paths.ROOT, root=root, base_dir=paths.ROOT,
                           resolution=resolution, params={"manifold_segments": SEGMENTS},
                           box=(np.asarray(box[0], float), np.asarray(box[1], float)))


def manifold_result(root: dict, resolution: int) -> dict:
    """manifold3d's exact Booleans of the tree (the harness's builder), measured here; status
    `empty` or `degenerate` when there is nothing to compare."""
    m = build_manifold.Builder(make_context(root, resolution)).build(root, np.eye(4))
    if m.status() != mf.Error.NoError:
        return {"status": "degenerate", "reason": str(m.status())}
    # solids that touch along a face or an edge leave sheets of zero volume
    parts = m.decompose()
    volumes = [part.volume() for part in parts]
    if all(v <= FLAT for v in volumes):
        return {"status": "empty"}
    if any(v <= FLAT for v in volumes):
        return {"status": "degenerate", "reason": f"a shell of zero volume among {len(volumes)}"}
    verts, faces = leaves.to_arrays(m)
    ms = measure.measure(verts, faces)
    if not ms["manifold"]:
        return {"status": "degenerate", "reason": "not a closed oriented 2-manifold"}
    return {"status": "ok", "measures": ms, "sharp_edges": measure.sharp_edges(verts, faces),
            "apart": _apart(parts)}


def _apart(parts: list) -> int:
    """The shells of manifold3d's result that stay apart when shells touching along an edge or
    at a point (gap 0: a pinch, which exact Booleans keep as separate shells) count as one."""
    label = list(range(len(parts)))
    find = lambda i: i if label[i] == i else find(label[i])
    for a, b in itertools.combinations(range(len(parts)), 2):
        if parts[a].min_gap(parts[b], 1e-3) <= 1e-9:
            label[find(a)] = find(b)
    return len({find(i) for i in range(len(parts))})


def solidkit_result(tree_file: Path, root: dict, resolution: int, timeout: float = 120) -> dict:
    """`solidkit --threads 1 mesh TREE --resolution N -o TREE.stl --json`, the STL measured here;
    its cell from the tree's bounds (make_context), which must give the grid it reports."""
    stl = Path(tree_file).with_suffix(".stl")
    cmd = [str(paths.solidkit_bin()), "--threads", "1", "mesh", str(tree_file),
           "--resolution", str(resolution), "-o", str(stl), "--json"]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if r.returncode != 0:
        return {"status": "error", "reason": f"exit {r.returncode}: {r.stderr.strip()[-400:]}",
                "command": " ".join(cmd)}
    report = json.loads(r.stdout)
    ms = measure.measure(*meshio.read_stl(stl))
    if not paths.keep_meshes():
        stl.unlink()  # remade by the command printed with any failure
    ctx = make_context(root, resolution)
    # solidkit's grid: ceil(extent / cell) cells per axis and a padding cell at each end
    cells = [int(math.ceil(e / ctx.cell - 1e-9)) + 2 for e in ctx.box[1] - ctx.box[0]]
    # Refinement for thin features meshes on a nested grid `refinement` times finer.
    factor = int(report.get("refinement", 1))
    if [c * factor for c in cells] != report["cells"]:
        return {"status": "error", "command": " ".join(cmd),
                "reason": f"grid {report['cells']} is not {factor} x the {cells} of the bounds "
                          f"{ctx.box} here"}
    return {"status": "ok", "report": report, "measures": ms, "cell": ctx.cell / factor,
            "command": " ".join(cmd)}


def has_cylinder(root: dict) -> bool:
    return "cylinder" in tree.node_types(root)


def compare(sk: dict, ref: dict, faceted: bool) -> dict:
    """The verdict on one tree: `problems` (every solidkit mesh closed, manifold, oriented, free
    of self-intersections; shells and genus equal to manifold3d's; volume within tolerance),
    `pinch` (the only problems are shells joined where manifold3d's shells touch: the known bug
    of fixtures/lattice/), `ratio` (|ΔV| over the volume tolerance: the harness's area term
    (xcheck/tolerance.py) with solidkit's cell and manifold3d's facet error, plus the chamfer
    term of manifold3d's creases)."""
    if sk["status"] != "ok":
        return {"problems": [f"solidkit failed: {sk['reason']}"], "pinch": False, "ratio": None,
                "volume_error": None, "surface_ratio": None}
    s, m = sk["measures"], ref["measures"]
    problems, topology = [], []
    for key in ("closed", "manifold", "oriented"):
        if not s[key]:
            problems.append(f"solidkit mesh not {key} (boundary {s['boundary_edges']}, non-manifold "
                            f"edges {s['non_manifold_edges']}, vertices {s['non_manifold_vertices']}, "
                            f"inconsistent {s['inconsistent_edges']})")
    si = sk["report"].get("self_intersections")
    if si != 0:
        problems.append(f"self_intersections {si}")
    for key in ("shells", "genus"):
        if s[key] != m[key]:
            topology.append(f"{key}: solidkit {s[key]}, manifold3d {m[key]}")
    facet = leaves.sagitta(RADIUS, SEGMENTS) if faceted else 0.0
    g = sk["cell"]
    surface = tolerance.volume_tol(m["area"] / m["volume"], g, 0.0, 0.0, facet) * m["volume"]
    tol = surface + tolerance.chamfer_tol(g, ref["sharp_edges"])
    dv = s["volume"] - m["volume"]
    if abs(dv) > tol:
        problems.append(f"volume: solidkit {s['volume']:.6g}, manifold3d {m['volume']:.6g}, "
                        f"difference {dv / m['volume']:+.3%} (tolerance {tol / m['volume']:.3%})")
    pinch = bool(topology) and not problems and ref["apart"] <= (s["shells"] or 0) < m["shells"]
    return {"problems": problems + topology, "pinch": pinch, "ratio": abs(dv) / tol,
            "volume_error": dv / m["volume"], "surface_ratio": abs(dv) / surface}


def run(seed: int, count: int, jobs: int = None, out: Path = None, max_trees: int = None) -> dict:
    """Trees 0, 1, … of `seed` until `count` have a non-empty, valid manifold3d result (the
    others are counted as skipped), each meshed by solidkit `jobs` at a time; every tree is
    written to OUT/lattice/tree-SEED-INDEX.json. Returns the counts, the worst volume ratio and
    each disagreement with its tree and both measures."""
    start = time.time()
    jobs = jobs or int(os.environ.get("CROSSCHECK_JOBS", os.cpu_count() or 2))
    out = Path(out or paths.out_dir() / "lattice")
    out.mkdir(parents=True, exist_ok=True)
    max_trees = max_trees or 3 * count
    trees, skipped = [], {"empty": [], "degenerate": []}
    for index in itertools.count():
        if len(trees) == count or index == max_trees:
            break
        t = generate(seed, index)
        ref = manifold_result(t["root"], t["resolution"])
        if ref["status"] != "ok":
            skipped[ref["status"]].append(index)
            continue
        t.update(index=index, ref=ref, file=str(out / f"tree-{seed}-{index}.json"))
        Path(t["file"]).write_text(json.dumps(t["root"], indent=1))
        trees.append(t)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda t: solidkit_result(t["file"], t["root"], t["resolution"]), trees))
    failures, pinches, volumes = [], [], []
    for t, sk in zip(trees, results):
        v = compare(sk, t["ref"], has_cylinder(t["root"]))
        if v["ratio"] is not None:
            volumes.append((v["ratio"], v["volume_error"], v["surface_ratio"], t["index"]))
        if v["problems"]:
            entry = {"seed": seed, "index": t["index"], "file": t["file"],
                     "resolution": t["resolution"], "problems": v["problems"],
                     "solidkit": _summary(sk), "manifold3d": _summary(t["ref"]),
                     "command": sk.get("command")}
            (pinches if v["pinch"] else failures).append(entry)
    worst = max(volumes, default=(None, None, None, None))
    summary = {"seed": seed, "compared": len(trees), "skipped": {k: len(v) for k, v in skipped.items()},
            "skipped_indices": skipped, "failures": failures, "pinches": pinches,
            "worst_volume_ratio": worst[0], "worst_volume_index": worst[3],
            "largest_volume_error": max((abs(v[1]) for v in volumes), default=None),
            "worst_surface_only": max(((v[2], v[3]) for v in volumes), default=None),
            "largest_cell": max((r["cell"] for r in results if r["status"] == "ok"), default=None),
            "elapsed_s": time.time() - start}
    (out / f"summary-{seed}.json").write_text(json.dumps(summary, indent=1))
    return summary


def _summary(r: dict) -> dict:
    if r["status"] != "ok":
        return {"status": r["status"], "reason": r.get("reason")}
    m = r["measures"]
    keep = {k: m[k] for k in ("shells", "genus", "volume", "area", "closed", "manifold", "oriented",
                              "vertices", "faces")}
    if "apart" in r:
        keep["shells_apart_at_pinches"] = r["apart"]
    if "report" in r:
        keep["self_intersections"] = r["report"].get("self_intersections")
        keep["cell"] = r["cell"]
    return keep


if __name__ == "__main__":
    import argparse
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--seed", type=int, default=13)
    p.add_argument("--count", type=int, default=1000)
    a = p.parse_args()
    res = run(a.seed, a.count)
    print(json.dumps({k: v for k, v in res.items() if k != "skipped_indices"}, indent=1))
