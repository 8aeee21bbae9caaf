//! Warnings to Python: every line through `warnings.warn` (a `UserWarning`), in the keyword
//! names of the Python API rather than the command line's flags.

use pyo3::prelude::*;

/// Issues every line of `warnings` through Python's `warnings.warn`.
pub fn warn_all(py: Python<'_>, warnings: &[String]) -> PyResult<()> {
    if warnings.is_empty() {
        return Ok(());
    }
    let warn = py.import("warnings")?.getattr("warn")?;
    for w in warnings {
        let w = crate::errors::pythonic(w);
        warn.call1((w, py.get_type::<pyo3::exceptions::PyUserWarning>(), 2))?;
    }
    Ok(())
}
