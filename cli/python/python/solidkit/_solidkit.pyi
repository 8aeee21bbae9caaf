"""Type stubs of the extension module ``solidkit._solidkit`` (re-exported by ``solidkit``)."""

from os import PathLike
from typing import Any, Callable, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

Vec3 = Union[Sequence[float], npt.ArrayLike]
NumOrVec3 = Union[float, Vec3]
Bounds = Tuple[Tuple[float, float, float], Tuple[float, float, float]]
Path = Union[str, "PathLike[str]"]
Progress = Callable[[str, int, int], Any]

class SolidkitError(Exception):
    """Base class of every error solidkit raises."""

class LoadError(SolidkitError):
    """A tree, script or .csg file that cannot be read (the message names file, line, column)."""

class MeshingError(SolidkitError):
    """A solid that cannot be meshed as asked (empty, unbounded, over the memory budget, ...)."""

class MeshIOError(SolidkitError):
    """A mesh file that cannot be read or written (the message names the file and place)."""

class Solid:
    """A solid: a CSG tree evaluated as a signed field (negative inside). Immutable."""

    @property
    def bbox(self) -> Bounds:
        """The bounding box ``((xmin, ymin, zmin), (xmax, ymax, zmax))``; infinite if unbounded."""
    @property
    def warnings(self) -> list[str]:
        """What the front end warned about when this solid (or a part of it) was loaded."""
    @property
    def kind(self) -> str:
        """The root node's kind, e.g. ``"sphere"`` or ``"union"``."""
    def translate(self, offset: Vec3) -> Solid:
        """Moved by ``offset``."""
    def rotate(self, axis: Vec3, degrees: float) -> Solid:
        """Rotated by ``degrees`` about ``axis`` (through the origin)."""
    def scale(self, factor: NumOrVec3) -> Solid:
        """Scaled by one factor or three."""
    def mirror(self, normal: Vec3) -> Solid:
        """Mirrored in the plane through the origin with this normal."""
    def affine(self, matrix: Sequence[Sequence[float]]) -> Solid:
        """Transformed by a 3 x 4 row-major affine matrix."""
    def offset(self, distance: float) -> Solid:
        """Grown by ``distance`` (shrunk when negative)."""
    def shell(self, thickness: float) -> Solid:
        """A hollow shell of the given thickness around the surface."""
    def color(self, color: Union[str, Sequence[float]], alpha: Optional[float] = None) -> Solid:
        """Painted: a CSS/SVG name, "#rrggbb[aa]" or 3 or 4 numbers in 0..1 (geometry unchanged)."""
    def __or__(self, other: Solid) -> Solid:
        """Union."""
    def __and__(self, other: Solid) -> Solid:
        """Intersection."""
    def __sub__(self, other: Solid) -> Solid:
        """Difference."""
    def to_json(self) -> str:
        """The JSON tree document of this solid (``solidkit mesh`` reads it back)."""
    def eval(
        self,
        points: npt.ArrayLike,
        *,
        gradients: bool = False,
        double: bool = False,
        threads: Optional[int] = None,
        out: Optional[npt.NDArray[np.float32]] = None,
    ) -> Any:
        """Field values at the points of an N x 3 array (negative inside).

        float32 values from the meshers' single-precision batch evaluator (into ``out`` when
        given), float64 with ``double=True``; with ``gradients=True`` a tuple ``(values,
        gradients)`` in double precision (N and N x 3). Runs on ``threads`` threads (default:
        all cores) with the GIL released. Large results reuse the memory of earlier results
        that have been freed.
        """
    def mesh(
        self,
        resolution: int = 128,
        *,
        method: Optional[Literal["mc", "dc"]] = None,
        tolerance: Optional[float] = None,
        bounds: Optional[Bounds] = None,
        refine: int = 32,
        max_memory: Optional[int] = None,
        threads: Optional[int] = None,
        progress: Optional[Progress] = None,
        simplify: Optional[float] = None,
        target_error: Optional[float] = None,
    ) -> Mesh:
        """A closed oriented 2-manifold mesh of the solid.

        ``resolution`` cells along the longest side of the bounding box (or of ``bounds``,
        which also clips the solid); ``method`` marching cubes (default) or dual contouring
        (``tolerance`` simplifies DC meshes; the default with ``target_error``); ``simplify=E``
        or ``target_error=E`` (dual contouring, then simplify) collapse edges while the surface
        stays within E model units, closed, manifold and of the same genus; refined up to ``refine`` times finer where
        features are thinner than a cell; refused above ``max_memory`` bytes (default half the
        machine's memory). ``progress(stage, done, total)`` is called on this thread; Ctrl-C
        raises KeyboardInterrupt after stopping the mesher.
        """

class Mesh:
    """A triangle mesh; its arrays are read-only."""

    def __init__(self, vertices: npt.ArrayLike, faces: npt.ArrayLike) -> None:
        """A mesh from an N x 3 vertex array and an M x 3 index array (copied)."""
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """Vertex positions, N x 3 float64."""
    @property
    def faces(self) -> npt.NDArray[np.int64]:
        """Triangles as vertex indices, M x 3 int64."""
    @property
    def face_colors(self) -> Optional[npt.NDArray[np.uint8]]:
        """Per-triangle colours, M x 4 uint8 (RGBA), or None when the tree had no colours."""
    @property
    def warnings(self) -> list[str]:
        """What may be wrong or missing in this mesh, one line each."""
    def report(
        self, *, self_intersections: bool = True, threads: Optional[int] = None
    ) -> dict[str, Any]:
        """The topology report with the keys of ``solidkit mesh --json``."""
    def save(self, path: Path, *, colors: bool = True) -> None:
        """Writes the mesh (.stl, .obj, .ply, .off, .3mf, .glb by extension), atomically;
        3MF, PLY, GLB and OFF carry ``face_colors`` unless ``colors=False``."""
    def to_trimesh(self) -> Any:
        """A ``trimesh.Trimesh`` with the same arrays."""
    def to_manifold(self) -> Any:
        """A ``manifold3d.Manifold`` of this mesh."""
    @staticmethod
    def from_trimesh(mesh: Any) -> Mesh:
        """The mesh of a ``trimesh.Trimesh``."""
    @staticmethod
    def from_manifold(manifold: Any) -> Mesh:
        """The mesh of a ``manifold3d.Manifold`` or ``manifold3d.Mesh``."""
    def __len__(self) -> int:
        """The number of triangles."""

def sphere(radius: float) -> Solid:
    """A sphere of ``radius`` at the origin."""

def cube(size: NumOrVec3) -> Solid:
    """An axis-aligned box centred at the origin (one edge length or three)."""

def box(size: NumOrVec3) -> Solid:
    """Same as ``cube``."""

def cuboid(size: NumOrVec3) -> Solid:
    """Same as ``cube``."""

def cylinder(radius: float, height: float) -> Solid:
    """A cylinder along z, centred at the origin."""

def cone(bottom: float, top: float, height: float) -> Solid:
    """A truncated cone along z, centred at the origin."""

def torus(major_radius: float, minor_radius: float) -> Solid:
    """A torus around z, centred at the origin."""

def plane(normal: Vec3, offset: float) -> Solid:
    """The half-space ``normal . p <= offset`` (unbounded)."""

def gyroid(thickness: float) -> Solid:
    """The gyroid sheet of the given thickness (unbounded)."""

def union(*solids: Solid) -> Solid:
    """The union of the solids."""

def intersection(*solids: Solid) -> Solid:
    """The intersection of the solids."""

def difference(base: Solid, *cutters: Solid) -> Solid:
    """``base`` minus every cutter."""

def smooth_union(*solids: Solid, radius: float) -> Solid:
    """A rounded union with blend ``radius``."""

def smooth_intersection(*solids: Solid, radius: float) -> Solid:
    """A rounded intersection with blend ``radius``."""

def smooth_difference(base: Solid, *cutters: Solid, radius: float) -> Solid:
    """``base`` smoothly minus the cutters."""

def load(
    path: Path,
    *,
    facets: Literal["exact", "openscad"] = "exact",
    allow: Optional[Sequence[Path]] = None,
    defines: Optional[Sequence[str]] = None,
) -> Solid:
    """A solid from a .json tree, .rhai script, OpenSCAD .csg file or .scad file (by extension).

    ``.scad`` files go through the installed OpenSCAD, with ``defines`` (``"name=value"``) as its
    ``-D`` options; in ``.rhai`` scripts each define is the constant ``name`` (``value`` a Rhai
    literal); defines for ``.json`` and ``.csg`` files are an error.
    """

def from_json(
    text: str,
    *,
    base_dir: Optional[Path] = None,
    allow: Optional[Sequence[Path]] = None,
    name: str = "<json>",
) -> Solid:
    """A solid from the text of a JSON tree (a document or one node)."""

def read(path: Path) -> Mesh:
    """Reads a mesh file (.stl, .obj, .ply, .off, .3mf, .glb)."""

def check(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    *,
    self_intersections: bool = True,
    threads: Optional[int] = None,
) -> dict[str, Any]:
    """The topology report of a mesh given as arrays (``solidkit check --json``'s keys)."""

def compare(
    a: Mesh, b: Mesh, *, samples: int = 100_000, threads: Optional[int] = None
) -> dict[str, Any]:
    """Both meshes' measures and their Hausdorff distance (``solidkit compare --json``)."""

def gen(
    suite: Literal["platonic", "sponge", "smooth", "csg", "random", "broken"],
    out_dir: Path,
    *,
    format: Literal["stl", "obj", "ply", "off", "3mf", "glb"] = "ply",
    seed: int = 0,
    resolution: int = 64,
    count: int = 8,
    threads: Optional[int] = None,
) -> dict[str, Any]:
    """Writes a suite of test solids with ground truth; returns ``manifest.json`` as a dict."""

class Curve:
    """A curve of the JSON format (``solidkit.curve(kind, **keys)``). Immutable."""

    @property
    def kind(self) -> str:
        """``"bezier"``, ``"hermite"``, ``"bspline"``, ``"nurbs"``, ``"interpolating"``,
        ``"cubic_through"``, ``"composite"`` or ``"formula"``."""
    @property
    def domain(self) -> Tuple[float, float]:
        """The parameter interval."""
    @property
    def closed(self) -> bool:
        """True when the curve ends where it starts."""
    def point(self, u: float) -> Tuple[float, float, float]:
        """The point at ``u`` (a ValueError outside the domain)."""
    def derivative(self, u: float) -> Tuple[float, float, float]:
        """The first derivative at ``u``."""
    def second_derivative(self, u: float) -> Tuple[float, float, float]:
        """The second derivative at ``u``."""
    def tangent(self, u: float) -> Tuple[float, float, float]:
        """The unit tangent at ``u``."""
    def length(self) -> float:
        """The arc length (Gauss-Legendre quadrature)."""
    def split(self, u: float) -> dict[str, Any]:
        """The de Casteljau split of the Bezier piece holding ``u``: ``left`` and ``right``
        (``points`` N x 3, ``weights``, ``interval``) and ``piece``."""
    def polyline(self, chord_error: float) -> np.ndarray:
        """Vertices (N x 3, read-only) of a polyline within ``chord_error`` of the curve."""
    def samples(self, n: int) -> np.ndarray:
        """``n`` points (N x 3, read-only) at equally spaced parameters."""

def curve_from_json(text: str) -> Curve:
    """A curve from the JSON text of one curve object."""
