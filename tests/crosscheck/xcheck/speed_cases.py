"""The cases of the speed comparison (bench_peers.py): one solid at one grid spacing h, as each
system sees it.

- solidkit: a benchmark model (`solidkit bench --model M --resolution R`, R cells over the
  model's domain) and the same solid as a JSON fixture (`solidkit mesh FIXTURE --resolution N`,
  N cells over the solid's bounding box); R and N are chosen so that both cells are h.
- the references: the solid's bounding box (`box`), the tree (`fixture`) and h.

Reference values a mesh is checked against: exact volumes and genera where there is a closed
form (sphere, Menger sponge); for the gyroid sheet, whose volume has no closed form, a seeded
Monte Carlo estimate of the exact field's volume (computed by `reference_volume`, with its
standard error).
"""
import json
import math
from dataclasses import dataclass

import numpy as np

from . import paths

SPHERE_RADIUS = 0.6
GYROID_SCALE = 30.0
GYROID_BALL = 25.0
GYROID_THICKNESS = 0.2
MENGER_PAD = 1.0 / 32.0

# System keys: what each (case, system) run does (speed_systems.py has the builders).
SOLIDKIT = "solidkit"
OPENVDB_SPHERE = "openvdb-sphere"      # createLevelSetSphere + convertToPolygons
OPENVDB_FIELD = "openvdb-field"        # numpy samples -> copyFromArray + convertToPolygons
OPENVDB_CSG = "openvdb-csg"            # the harness's level-set CSG + convertToPolygons
MANIFOLD_LEVEL_SET = "manifold3d-level-set"  # Manifold.level_set, Python callback per point
MANIFOLD_EXACT = "manifold3d-exact"    # exact mesh Booleans of Manifold.cube


@dataclass(frozen=True)
class Case:
    name: str
    model: str               # solidkit bench model
    bench_resolution: int    # R: cells over the model's domain
    fixture: str             # the same solid as a JSON tree (relative to the repository)
    mesh_resolution: int     # N: cells over the solid's bbox (solidkit mesh)
    cell: float              # h
    half: float              # the solid's bbox is [-half, half]^3
    volume: float            # reference volume
    volume_how: str
    genus: int = None        # exact genus (summed over shells), None when not known
    systems: tuple = ()

    @property
    def box(self):
        return (np.full(3, -self.half), np.full(3, self.half))

    def tree(self) -> dict:
        doc = json.loads((paths.ROOT / self.fixture).read_text())
        return doc["root"] if "root" in doc else doc


def _cells(extent: float, cell: float, what: str) -> int:
    n = extent / cell
    if abs(n - round(n)) > 1e-9:
        raise ValueError(f"{what}: {extent} is not a whole number of cells of {cell}")
    return int(round(n))


def sphere(resolution: int, systems) -> Case:
    """The benchmark sphere (radius 0.6, domain [-1, 1]^3); R must be a multiple of 5."""
    h = 2.0 / resolution
    return Case(
        name=f"sphere {resolution}", model="sphere", bench_resolution=resolution,
        fixture="fixtures/bench/sphere.json",
        mesh_resolution=_cells(2 * SPHERE_RADIUS, h, "sphere"), cell=h, half=SPHERE_RADIUS,
        volume=4.0 / 3.0 * math.pi * SPHERE_RADIUS ** 3, volume_how="4/3 pi r^3", genus=0,
        systems=tuple(systems))


def gyroid(resolution: int, systems, volume: float, how: str) -> Case:
    """The gyroid sheet clipped to a ball (domain [-1, 1]^3, ball radius 25/30); R a multiple of 6."""
    h = 2.0 / resolution
    half = GYROID_BALL / GYROID_SCALE
    return Case(
        name=f"gyroid-sphere {resolution}", model="gyroid-sphere", bench_resolution=resolution,
        fixture="fixtures/bench/gyroid-sphere.json",
        mesh_resolution=_cells(2 * half, h, "gyroid-sphere"), cell=h, half=half,
        volume=volume, volume_how=how, systems=tuple(systems))


def menger(level: int, resolution: int, systems) -> Case:
    """Menger sponge `level` (unit cube, domain padded by 1/32); R a multiple of 17."""
    h = (1.0 + 2 * MENGER_PAD) / resolution
    genus = (21 * 20 ** level + 38 * 8 ** level - 59) // 133
    return Case(
        name=f"menger-{level} {resolution}", model=f"menger-{level}", bench_resolution=resolution,
        fixture=f"fixtures/crosscheck/menger_{level}.json",
        mesh_resolution=_cells(1.0, h, "menger"), cell=h, half=0.5,
        volume=(20.0 / 27.0) ** level, volume_how="(20/27)^L", genus=genus,
        systems=tuple(systems))


def reference_volume(samples: int = 20_000_000, seed: int = 1) -> tuple:
    """Volume of the gyroid sheet in its ball by Monte Carlo over the ball's bbox (in gyroid
    coordinates: |P| <= 25 and |g(P)| <= 0.2), and its standard error; exact field, no grid."""
    rng = np.random.default_rng(seed)
    inside = 0
    chunk = 2_000_000
    done = 0
    while done < samples:
        n = min(chunk, samples - done)
        x, y, z = rng.uniform(-GYROID_BALL, GYROID_BALL, (3, n))
        g = np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)
        inside += int(np.count_nonzero((np.abs(g) <= GYROID_THICKNESS)
                                       & (x * x + y * y + z * z <= GYROID_BALL ** 2)))
        done += n
    frac = inside / samples
    box = (2 * GYROID_BALL / GYROID_SCALE) ** 3
    return frac * box, box * math.sqrt(frac * (1 - frac) / samples)


# The Python-callback level set only where it finishes in well under a minute.
MANIFOLD_LEVEL_SET_MAX = {"sphere": 200, "gyroid-sphere": 240}


def case(model: str, resolution: int, volume: float = None, how: str = "") -> Case:
    """The case of `model` at R = `resolution` with every system that builds it natively."""
    if model == "sphere":
        systems = [SOLIDKIT, OPENVDB_SPHERE]
    elif model == "gyroid-sphere":
        systems = [SOLIDKIT, OPENVDB_FIELD]
    elif model.startswith("menger-"):
        return menger(int(model.split("-", 1)[1]), resolution, [SOLIDKIT, OPENVDB_CSG, MANIFOLD_EXACT])
    else:
        raise ValueError(f"unknown model '{model}' (sphere, gyroid-sphere, menger-L)")
    if resolution <= MANIFOLD_LEVEL_SET_MAX[model]:
        systems.append(MANIFOLD_LEVEL_SET)
    if model == "sphere":
        return sphere(resolution, systems)
    return gyroid(resolution, systems, volume, how)


# The default run: each model at two spacings (about 9 minutes on one core).
DEFAULT = [("sphere", 160), ("sphere", 640), ("gyroid-sphere", 240), ("gyroid-sphere", 360),
           ("menger-3", 136), ("menger-3", 272)]
