//! Distance measures between surfaces: the nearest point of a mesh to a query point (the kernel's
//! triangle bounding volume hierarchy, [`TriangleTree`]), the exact nearest
//! point of a triangle, deterministic surface samples, and the one-sided and symmetric Hausdorff
//! distances between meshes or from a point set (e.g. samples of an exact surface) to a mesh,
//! and [`compare`]: two meshes' key measures and distances side by side.
//!
//! ```
//! use glam::DVec3;
//! use solidkit_meshing::IndexedMesh;
//! use solidkit_meshing::measure::{TriangleTree, hausdorff};
//!
//! let tri = |z: f64| IndexedMesh::new(
//!     vec![DVec3::new(0.0, 0.0, z), DVec3::new(1.0, 0.0, z), DVec3::new(0.0, 1.0, z)],
//!     vec![[0, 1, 2]],
//! );
//! let tree = TriangleTree::new(&tri(0.0)).unwrap();
//! assert_eq!(tree.nearest(DVec3::new(0.2, 0.2, 3.0)).distance, 3.0);
//! let h = hausdorff(&tri(0.0), &tri(0.5), 100).unwrap();
//! assert!((h.symmetric - 0.5).abs() < 1e-12);
//! ```

mod compare;
mod error;
mod hausdorff;
mod rng;
mod sample;
mod tree;
mod triangle;

#[cfg(test)]
mod tests;

pub use compare::{Comparison, compare};
pub use error::MeasureError;
pub use hausdorff::{Hausdorff, OneSided, hausdorff, hausdorff_with, one_sided, samples_to_mesh};
pub use sample::SurfaceSamples;
pub use tree::{Nearest, TriangleTree};
pub use triangle::{closest_point_on_segment, closest_point_on_triangle};
