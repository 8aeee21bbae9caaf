//! Polygonizers, the half-edge mesh, topology reports and mesh I/O of solidkit.
//!
//! Data flow: a signed field (from `solidkit-kernel`) is polygonized by [`marching_cubes`] into an
//! [`IndexedMesh`]; any indexed mesh (polygonized or read from a file by [`io`]) can be verified by
//! [`topology::TopologyReport`] and navigated as a [`halfedge::HalfEdgeMesh`].
#![warn(missing_docs)]

pub mod dual_contouring;
pub mod grid;
pub mod halfedge;
pub mod intersect;
pub mod io;
pub mod marching_cubes;
pub mod measure;
pub mod octree;
pub mod pipeline;
pub mod refine;
pub mod render;
pub mod repair;
pub mod sink;
pub mod subdivision;
pub mod suites;
pub mod topology;

pub use halfedge::HalfEdgeMesh;
pub use sink::MeshSink;
pub use solidkit_kernel::IndexedMesh;
pub use topology::{ReportOptions, TopologyReport};
