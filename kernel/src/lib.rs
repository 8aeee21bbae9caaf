//! The solid model of solidkit: CSG trees of primitives, evaluated as signed fields.
//!
//! # A tour of the data flow
//!
//! 1. **Build** a [`Solid`]: a tree of [`Primitive`]s combined by Booleans (union, intersection,
//!    difference, their n-ary and smooth forms) and [`Transform`]s. The primitives are the
//!    quadrics (sphere, cuboid, cylinder, cone, torus, ellipsoid, the general 10-coefficient
//!    [`primitive::quadric`]), half-spaces, gyroids, blobby metaballs ([`primitive::blob`]),
//!    sweeps ([`primitive::sweep`]: extrusions, revolutions, sweeps along curves, ruled surfaces,
//!    lofts, over the curves of [`curve`] and profiles of [`profile`]), polyhedra ([`polyhedra`]:
//!    Platonic solids and duals, prisms, any closed mesh through a BVH of its triangles in
//!    [`bvh`]) and height fields. Build trees in code ([`Solid::sphere`], [`Solid::union`], …) or
//!    read them from the JSON tree format with [`json`]; files a tree names are read through the
//!    confined access of [`files`].
//! 2. **Check** it with [`Solid::validate`] (typed [`KernelError`]s) and bound it with
//!    [`Solid::bbox`].
//! 3. **Lower** it to a [`Program`] with [`Solid::compile`]: a flat list of [`Instr`]uctions over
//!    registers. A program evaluates a field value at a point (`value`), values over slices of
//!    points in single precision (`eval_many`, vectorized), gradients, and an [`Interval`] over
//!    a box (`interval_with`) after which `prune` returns a shorter program valid in that box.
//!    The field is negative inside and a distance bound everywhere; exact zeros are settled
//!    symbolically (`program::perturb`) so coincident faces never invent surfaces.
//!    All of this is the [`Evaluator`] trait ([`eval`]), which the meshers are generic over.
//! 4. **Mesh** it: the `solidkit-meshing` crate polygonizes a program on a grid (its `pipeline`
//!    module is the one path), and [`tessellate`] and [`patch`] give exact triangulations of
//!    surfaces where one exists.
//!
//! Every whole-tree operation (build, clone, drop, compare, validate, lower, evaluate, read, write)
//! uses explicit work lists, so trees of any depth are safe.
//!
//! ```
//! use glam::DVec3;
//! use solidkit_kernel::{Aabb, Solid};
//!
//! // A unit cube with a hole of radius 0.25 drilled along z.
//! let cube = Solid::cuboid(DVec3::ONE);
//! let drill = Solid::cylinder(0.25, 2.0);
//! let part = cube.difference(&drill);
//! part.validate().unwrap();
//!
//! let program = part.compile();
//! assert!(program.value(DVec3::new(0.4, 0.4, 0.0)) < 0.0); // in the material
//! assert!(program.value(DVec3::ZERO) > 0.0); // in the hole
//! // Over a box inside the hole the field is positive everywhere.
//! let hole = Aabb::new(DVec3::splat(-0.1), DVec3::splat(0.1));
//! assert!(program.interval(&hole).lo > 0.0);
//! ```
#![warn(missing_docs)]

mod aabb;
pub mod bvh;
pub mod closest;
pub mod color;
pub mod curve;
mod error;
pub mod eval;
mod field;
pub mod files;
mod interval;
pub mod json;
mod mesh;
#[cfg(feature = "models")]
pub mod models;
pub mod patch;
pub mod polyhedra;
pub mod primitive;
pub mod profile;
pub mod program;
pub mod simd;
mod solid;
pub mod surface;
pub mod swept;
pub mod tessellate;
mod transform;
pub mod triangulate;

pub use aabb::Aabb;
pub use color::{ColorSkeleton, ColoredPart, Rgba};
pub use error::KernelError;
pub use eval::Evaluator;
pub use field::Field;
pub use interval::Interval;
pub use mesh::IndexedMesh;
pub use primitive::{Primitive, Shape};
pub use program::{Instr, Program};
pub use solid::{Node, NodeKind, Solid};
pub use transform::{Transform, TransformError, TransformSpec, singular_value_range};

use glam::DVec3;

impl Solid {
    /// Lowers the tree to a [`Program`] for evaluation (same as [`Solid::lower`]).
    pub fn compile(&self) -> Program {
        self.lower()
    }

    /// Field value at `p` (lowers the tree on every call: use [`Solid::compile`] for many points).
    pub fn value(&self, p: DVec3) -> f64 {
        self.compile().value(p)
    }

    /// Field gradient at `p` (lowers the tree on every call).
    pub fn gradient(&self, p: DVec3) -> DVec3 {
        self.compile().gradient(p)
    }

    /// An interval containing the field's values over a box (lowers the tree on every call).
    pub fn interval(&self, b: &Aabb) -> Interval {
        self.compile().interval(b)
    }
}
