//! The JSON tree format (`"format": "solidkit-tree", "version": 1`): reading with JSON paths and
//! line/column in every error, and lossless writing. Both directions use work lists, so trees of any
//! depth round-trip.
//!
//! ```json
//! {"format": "solidkit-tree", "version": 1,
//!  "root": {"type": "difference", "children": [
//!     {"type": "sphere", "radius": 1.0},
//!     {"type": "box", "size": [1.2, 1.2, 1.2]}]}}
//! ```
//! Node types and their keys: `sphere` (radius), `box` (size: number or [x, y, z]), `cylinder`
//! (radius, height), `cone` (bottom_radius, top_radius, height), `torus` (major_radius,
//! minor_radius), `plane` (normal, offset; inside is `n̂ · p ≤ offset`), `union` / `intersection` /
//! `difference` (children), `translate` (offset), `rotate` (axis, degrees), `scale` (factor: number
//! or [x, y, z]), `mirror` (normal), `affine` (matrix: 3 rows of 4); transforms take one `child`.
//! Polyhedra: `platonic` (solid: tetrahedron | cube | octahedron | dodecahedron | icosahedron;
//! circumradius or edge), `polyhedron` (vertices: [[x, y, z], …], faces: [[i, j, k, …], …],
//! counter-clockwise from outside), `mesh` (path of an STL/OBJ/PLY/OFF file, loaded through a
//! [`MeshResolver`]: see [`from_str_with`]), `prism` (polygon: [[x, y], …], optional holes,
//! direction), `subdivide` (scheme: catmull-clark | loop | butterfly | doo-sabin, levels, and a
//! polyhedral `child`; computed by the [`MeshResolver`]), `dual` (a convex polyhedral `child`:
//! one vertex per face centroid, one face per vertex), `swept_volume` (a bounded `child` moved
//! along a `path` curve, `frame` rmf | fixed, optional `tolerance`; read as the union of the
//! child's copies along the path, see [`crate::swept`]).
//! Quadrics: `ellipsoid` (radii), `quadric` (coefficients {a, b, c, f, g, h, p, q, r, d}, bounds),
//! `elliptic_cylinder` / `elliptic_cone` / `elliptic_paraboloid` / `hyperbolic_paraboloid`
//! (radii [a, b], bounds), `hyperboloid_one_sheet` / `hyperboloid_two_sheets` (radii, bounds);
//! bounds are `[[x, y, z], [x, y, z]]`. Metaballs: `blob` (threshold, balls: [{center, strength,
//! sharpness}]). Height fields: `heightfield` (min [x, y], max [x, y], base, and one of `bezier`,
//! `samples` with optional `interpolation`, or `png` with `heights`). Sweeps: `extrude` (profile,
//! height, twist, scale), `revolve` (profile, angle), `sweep` (profile, path), `loft` (bottom, top,
//! height), `ruled` (bottom, top); profiles `circle` / `rectangle` / `polygon` / `curve` (a closed
//! curve, flattened) / `radial` (rho formula in u); curves `bezier` / `hermite` / `bspline` /
//! `nurbs` / `interpolating` / `cubic_through` / `composite` / `formula` (see [`curve_from_str`]
//! for curve files). Others: `gyroid` (thickness),
//! `smooth_union` / `smooth_intersection` / `smooth_difference` (radius, children), `offset`
//! (distance, child), `shell` (thickness, child).
//! Any node may carry a `comment` string.

mod document;
mod read;
mod write;

pub use crate::primitive::{MeshResolver, NoMeshResolver};
pub use read::{curve_from_str, from_str, from_str_with};
pub use write::to_string;

/// The value of the envelope's `format` key.
pub const FORMAT: &str = "solidkit-tree";
/// The version of the format this build reads and writes.
pub const VERSION: u32 = 1;

#[cfg(test)]
mod tests;
