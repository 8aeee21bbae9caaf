//! `solidkit._solidkit`, the extension module of the Python package `solidkit`: CSG trees built
//! or loaded ([`solid`]), their signed fields evaluated on numpy arrays ([`field`]), meshed by the
//! library's pipeline into numpy arrays ([`meshing`], [`mesh`]), meshes read, checked and compared
//! ([`tools`]), test suites generated ([`suite`]) and curves evaluated ([`curve`]). Long calls release the GIL, run on rayon's
//! threads and stay interruptible ([`run`]); every error is one of the exceptions of [`errors`],
//! with the command line's message.
//!
//! The Python layer (`python/solidkit/__init__.py`) re-exports this module, adds `node()` for
//! every other family of the JSON tree format and documents the whole API in its type stubs.

mod curve;
mod deinterleave;
mod errors;
mod field;
mod mesh;
mod meshing;
mod recycle;
mod run;
mod solid;
mod suite;
mod tools;
mod warn;

use pyo3::prelude::*;

/// The extension module.
#[pymodule]
fn _solidkit(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    solid::register(m)?;
    curve::register(m)?;
    mesh::register(m)?;
    tools::register(m)?;
    suite::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
