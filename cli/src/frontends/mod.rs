//! Front ends: languages other than the JSON tree that describe a solid (Rhai scripts, OpenSCAD
//! `.csg` files). Each turns a source text into a [`solidkit_kernel::Solid`].

pub mod csg;
pub mod rhai;
