//! The solid model of solidkit: CSG trees of primitives, evaluated as signed fields.
//!
//! A [`Solid`] is a tree of primitives (sphere, box, cylinder, cone, torus, half-space), Booleans
//! (union, intersection, difference, n-ary) and transforms. Its field is negative inside, positive
//! outside and a distance bound everywhere (Lipschitz constant 1). For many evaluations lower it to
//! a [`Program`] with [`Solid::compile`]; the [`json`] module reads and writes the JSON tree format.
//!
//! Every whole-tree operation (build, clone, drop, compare, validate, lower, evaluate, read, write)
//! uses explicit work lists, so trees of any depth are safe.
#![warn(missing_docs)]

mod aabb;
pub mod bvh;
pub mod closest;
pub mod curve;
mod error;
mod field;
pub mod files;
mod interval;
pub mod json;
mod mesh;
pub mod models;
pub mod patch;
pub mod polyhedra;
pub mod primitive;
pub mod profile;
pub mod program;
pub mod simd;
mod solid;
pub mod tessellate;
mod transform;
pub mod triangulate;

pub use aabb::Aabb;
pub use error::KernelError;
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
