//! The exceptions of the package: `SolidkitError` and one subclass per kind of failure, each
//! carrying the command line's message (`FILE:LINE:COLUMN: problem` for inputs).

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(
    solidkit,
    SolidkitError,
    PyException,
    "Base class of every error solidkit raises."
);
create_exception!(
    solidkit,
    LoadError,
    SolidkitError,
    "A tree, script or .csg file that cannot be read (the message names file, line and column)."
);
create_exception!(
    solidkit,
    MeshingError,
    SolidkitError,
    "A solid that cannot be meshed as asked (empty, unbounded, over the memory budget, ...)."
);
create_exception!(
    solidkit,
    MeshIOError,
    SolidkitError,
    "A mesh file that cannot be read or written (the message names the file and place)."
);

/// Adds the exception classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("SolidkitError", py.get_type::<SolidkitError>())?;
    m.add("LoadError", py.get_type::<LoadError>())?;
    m.add("MeshingError", py.get_type::<MeshingError>())?;
    m.add("MeshIOError", py.get_type::<MeshIOError>())?;
    Ok(())
}

/// A [`LoadError`] with `e`'s message.
pub fn load(e: impl std::fmt::Display) -> PyErr {
    LoadError::new_err(e.to_string())
}

/// A [`MeshingError`] with `e`'s message, in Python's words.
pub fn meshing(e: impl std::fmt::Display) -> PyErr {
    MeshingError::new_err(pythonic(&e.to_string()))
}

/// A pipeline message with the command line's option names replaced by the keyword arguments
/// of `Solid.mesh`.
pub fn pythonic(message: &str) -> String {
    message
        .replace("--resolution", "resolution")
        .replace("--max-memory", "max_memory")
        .replace("--refine-budget", "the refinement budget")
        .replace("--refine", "refine")
        .replace("--bounds", "bounds")
        .replace("--method dc", "method='dc'")
        .replace("--tolerance", "tolerance")
}

/// A [`MeshIOError`] with `e`'s message.
pub fn io(e: impl std::fmt::Display) -> PyErr {
    MeshIOError::new_err(e.to_string())
}

/// A plain [`SolidkitError`] with `e`'s message.
pub fn other(e: impl std::fmt::Display) -> PyErr {
    SolidkitError::new_err(e.to_string())
}
