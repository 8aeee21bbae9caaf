//! Meshes from elsewhere: `read(path)`, `check(vertices, faces)` (the report `solidkit check`
//! prints) and `compare(a, b)` (both reports and the symmetric Hausdorff distance, as
//! `solidkit compare --json`).

use crate::errors;
use crate::mesh::{PyMesh, indexed_from_arrays, report_dict};
use crate::run::interruptible;
use numpy::{AllowTypeChange, PyArrayLike2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use serde_json::Value;
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::measure::{TriangleTree, compare as compare_meshes};
use std::path::PathBuf;

/// The most surface samples `compare` takes per mesh (as on the command line).
const MAX_SAMPLES: usize = 10_000_000;

/// Reads a mesh file (.stl, .obj, .ply, .off, .3mf, .glb by extension).
#[pyfunction]
fn read(py: Python<'_>, path: PathBuf) -> PyResult<PyMesh> {
    let mesh = py.detach(|| read_mesh(&path)).map_err(errors::io)?;
    PyMesh::from_indexed(py, mesh, Vec::new(), Value::Object(Default::default()))
}

/// The topology report of the mesh given by an N × 3 vertex array and an M × 3 face array:
/// closed, manifold, oriented, shells, genus, volume, defects and self-intersections (a dict
/// with the keys of `solidkit check --json`).
#[pyfunction(signature = (vertices, faces, *, self_intersections = true, threads = None))]
fn check<'py>(
    py: Python<'py>,
    vertices: PyArrayLike2<'py, f64, AllowTypeChange>,
    faces: PyArrayLike2<'py, i64, AllowTypeChange>,
    self_intersections: bool,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let mesh = indexed_from_arrays(py, &vertices, &faces)?;
    report_dict(
        py,
        &mesh,
        self_intersections,
        threads,
        Vec::new(),
        &Value::Null,
    )
}

/// Both meshes' key measures and their symmetric Hausdorff distance, from `samples`
/// area-weighted surface points per mesh (`solidkit compare --json`'s dict).
#[pyfunction(signature = (a, b, *, samples = 100_000, threads = None))]
fn compare<'py>(
    py: Python<'py>,
    a: &PyMesh,
    b: &PyMesh,
    samples: usize,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    if !(1..=MAX_SAMPLES).contains(&samples) {
        return Err(PyValueError::new_err(format!(
            "samples must be 1 to {MAX_SAMPLES}, got {samples}"
        )));
    }
    let (ma, mb) = (a.indexed(), b.indexed());
    let v = interruptible(py, threads, None, &|| {}, || -> Result<Value, String> {
        let (ta, tb) = rayon::join(|| TriangleTree::new(ma), || TriangleTree::new(mb));
        let ta = ta.map_err(|e| format!("first mesh: {e}"))?;
        let tb = tb.map_err(|e| format!("second mesh: {e}"))?;
        Ok(compare_meshes(ma, &ta, mb, &tb, samples).to_json())
    })?
    .map_err(errors::meshing)?;
    py.import("json")?.call_method1("loads", (v.to_string(),))
}

/// Adds the functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    Ok(())
}
