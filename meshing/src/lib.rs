//! Polygonizers, the half-edge mesh, topology reports and mesh I/O of solidkit.
//!
//! # A tour of the data flow
//!
//! 1. **Grid.** A [`grid::GridSpec`] places cubic cells over a domain (padded around a solid's
//!    bounding box, or exactly covering a box); it refuses grids that single-precision
//!    coordinates cannot represent faithfully.
//! 2. **Mesh.** The [`pipeline`] takes a `solidkit_kernel::Solid` and typed [`pipeline::MeshOptions`]
//!    (method, resolution, domain, tolerance, refinement limits, cancellation, progress) and
//!    runs one of two polygonizers on the sparse [`octree`]: marching cubes (the default; its
//!    sign rule and case tables in [`marching_cubes`]) or [`dual_contouring`] (sharp features,
//!    optional simplification). The octree culls and prunes the program by intervals, samples
//!    only bricks the surface may cross, and scans them for features thinner than a cell, which
//!    [`refine`] meshes again on finer nested grids. The result is an [`IndexedMesh`], closed
//!    and 2-manifold by construction; [`sink::MeshSink`] receives triangles as they are made.
//! 3. **Verify.** [`TopologyReport`] counts what matters (closed, manifold, oriented, shells,
//!    genus per shell, V − E + F, area, volume, self-intersections through [`intersect`]);
//!    [`halfedge::HalfEdgeMesh`] navigates a mesh; [`measure`] gives Hausdorff distances.
//! 4. **Read, write, fix, look.** [`io`] reads and writes STL, OBJ, OFF, PLY, 3MF and GLB
//!    (hostile input gets located errors); [`repair`] closes and re-orients broken meshes;
//!    [`subdivision`] refines meshes; [`render`] draws fields and meshes to images.
//!
//! The generators of test solids with exact ground truth (`suites`, behind the `suites` feature)
//! build on the same path.
//!
//! ```
//! use solidkit_kernel::Solid;
//! use solidkit_meshing::pipeline::{Method, MeshOptions, mesh_solid};
//!
//! // A torus-like ring: a cylinder with a cylinder removed, meshed by dual contouring.
//! let ring = Solid::cylinder(1.0, 0.5).difference(&Solid::cylinder(0.5, 1.0));
//! let options = MeshOptions::new(48).method(Method::Dc);
//! let meshed = mesh_solid(&ring, &options).unwrap();
//! let report = meshed.report(&Default::default());
//! assert!(report.closed && report.manifold);
//! assert_eq!((report.shells, report.genus), (1, Some(1)));
//! let exact = std::f64::consts::PI * (1.0 - 0.25) * 0.5;
//! assert!((report.volume - exact).abs() < 0.02 * exact);
//! ```
#![warn(missing_docs)]

pub mod colors;
pub mod curvature;
pub mod dual_contouring;
pub mod grid;
pub mod halfedge;
pub mod intersect;
pub mod io;
pub mod marching_cubes;
pub mod measure;
pub mod octree;
mod pieces;
pub mod pipeline;
pub mod polyhedral;
pub mod refine;
pub mod render;
pub mod repair;
pub mod simplify;
pub mod sink;
mod stars;
pub mod subdivision;
#[cfg(feature = "suites")]
pub mod suites;
pub mod topology;
mod usable;
mod used;
mod window_stars;

pub use halfedge::HalfEdgeMesh;
pub use sink::{MeshSink, VertexIds};
pub use solidkit_kernel::IndexedMesh;
pub use topology::{ReportOptions, SelfIntersectionsMethod, TopologyReport};
