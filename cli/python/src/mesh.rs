//! `Mesh`: a triangle mesh as two read-only numpy arrays, `vertices` (N × 3 float64, handed over
//! from the mesher without a copy) and `faces` (M × 3 int64), with the topology report, file
//! output and conversions to and from trimesh and manifold3d.

use crate::errors;
use crate::run::interruptible;
use numpy::{
    AllowTypeChange, PyArray1, PyArray2, PyArrayLike2, PyArrayMethods, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::Value;
use solidkit_meshing::colors::{DEFAULT_COLOR, FaceColors};
use solidkit_meshing::io::{WriteOptions, write_colored_mesh_with};
use solidkit_meshing::pipeline::{Meshed, warnings};
use solidkit_meshing::{IndexedMesh, ReportOptions, TopologyReport};
use std::path::PathBuf;

/// A triangle mesh (immutable: its arrays are read-only; make a new `Mesh` to change it).
/// What a mesh run was asked for, as the report repeats it.
pub struct Asked<'a> {
    /// Cells along the longest side.
    pub resolution: usize,
    /// `"mc"` or `"dc"`.
    pub method: &'a str,
    /// The simplification distance, if any.
    pub simplify: Option<f64>,
    /// `target_error`, if given.
    pub target_error: Option<f64>,
}

#[pyclass(module = "solidkit", name = "Mesh", frozen)]
pub struct PyMesh {
    vertices: Py<PyArray2<f64>>,
    faces: Py<PyArray2<i64>>,
    mesh: IndexedMesh,
    warnings: Vec<String>,
    info: Value,
    pub(crate) colors: Option<FaceColors>,
}

/// `v` as a read-only array.
fn frozen<'py, T: numpy::Element>(a: Bound<'py, PyArray2<T>>) -> PyResult<Bound<'py, PyArray2<T>>> {
    let kw = PyDict::new(a.py());
    kw.set_item("write", false)?;
    a.call_method("setflags", (), Some(&kw))?;
    Ok(a)
}

/// The vertex array of `positions`, reusing their buffer (a `DVec3` is three `f64`s).
fn vertex_array(py: Python<'_>, positions: Vec<glam::DVec3>) -> PyResult<Bound<'_, PyArray2<f64>>> {
    let n = positions.len();
    let flat: Vec<f64> = match bytemuck::allocation::try_cast_vec(positions) {
        Ok(v) => v,
        Err((_, v)) => v.iter().flat_map(|p| p.to_array()).collect(),
    };
    frozen(PyArray1::from_vec(py, flat).reshape([n, 3])?)
}

/// The face array of `triangles`.
fn face_array<'py>(py: Python<'py>, triangles: &[[u32; 3]]) -> PyResult<Bound<'py, PyArray2<i64>>> {
    let flat: Vec<i64> = py.detach(|| triangles.iter().flat_map(|t| t.map(i64::from)).collect());
    frozen(PyArray1::from_vec(py, flat).reshape([triangles.len(), 3])?)
}

/// The mesh of an N × 3 vertex array and an M × 3 face array, indices checked.
pub fn indexed_from_arrays(
    py: Python<'_>,
    vertices: &PyArrayLike2<'_, f64, AllowTypeChange>,
    faces: &PyArrayLike2<'_, i64, AllowTypeChange>,
) -> PyResult<IndexedMesh> {
    let (vs, fs) = (vertices.shape(), faces.shape());
    if vs[1] != 3 || fs[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "vertices must be N x 3 and faces M x 3, got {} x {} and {} x {}",
            vs[0], vs[1], fs[0], fs[1]
        )));
    }
    if vs[0] > u32::MAX as usize {
        return Err(PyValueError::new_err("more than 2^32 vertices"));
    }
    let v = vertices.as_array();
    let f = faces.as_array();
    py.detach(|| {
        let positions: Vec<glam::DVec3> = v
            .rows()
            .into_iter()
            .map(|r| glam::DVec3::new(r[0], r[1], r[2]))
            .collect();
        let n = positions.len() as i64;
        let mut triangles = Vec::with_capacity(fs[0]);
        for (i, r) in f.rows().into_iter().enumerate() {
            let t = [r[0], r[1], r[2]];
            if let Some(bad) = t.iter().find(|&&k| k < 0 || k >= n) {
                return Err(PyValueError::new_err(format!(
                    "face {i} refers to vertex {bad}, but there are {n} vertices"
                )));
            }
            triangles.push(t.map(|k| k as u32));
        }
        Ok(IndexedMesh::new(positions, triangles))
    })
}

impl PyMesh {
    /// A mesh of `mesh`, its arrays made from it.
    pub fn from_indexed(
        py: Python<'_>,
        mesh: IndexedMesh,
        warnings: Vec<String>,
        info: Value,
    ) -> PyResult<PyMesh> {
        let faces = face_array(py, &mesh.triangles)?.unbind();
        let vertices = vertex_array(py, mesh.positions.clone())?.unbind();
        Ok(PyMesh {
            vertices,
            faces,
            mesh,
            warnings,
            info,
            colors: None,
        })
    }

    /// The mesh the pipeline made, with what it did in `info`.
    pub fn from_meshed(
        py: Python<'_>,
        meshed: Meshed,
        colors: Option<FaceColors>,
        warnings: Vec<String>,
        asked: Asked<'_>,
    ) -> PyResult<PyMesh> {
        let info = serde_json::json!({
            "resolution": asked.resolution,
            "method": asked.method,
            "simplify": asked.simplify,
            "target_error": asked.target_error,
            "simplify_collapses": meshed.simplified.map(|s| s.collapses),
            "cells": meshed.spec.cells,
            "cell": meshed.spec.cell,
            "refinement": meshed.factor,
            "samples_total": meshed.samples_total,
            "thin": meshed.stats.thin,
            "samples_evaluated": meshed.stats.samples_evaluated,
            "program_length": meshed.program_length,
            "lost_solid": meshed.lost_solid,
            "colors": colors.as_ref().map_or(0, |c| c.used()),
        });
        let mut mesh = PyMesh::from_indexed(py, meshed.mesh, warnings, info)?;
        mesh.colors = colors;
        Ok(mesh)
    }

    /// The Rust mesh.
    pub fn indexed(&self) -> &IndexedMesh {
        &self.mesh
    }
}

/// The topology report of `mesh` as a dict with the JSON report's keys, plus `warnings`.
pub fn report_dict<'py>(
    py: Python<'py>,
    mesh: &IndexedMesh,
    self_intersections: bool,
    threads: Option<usize>,
    mut warnings: Vec<String>,
    extra: &Value,
) -> PyResult<Bound<'py, PyAny>> {
    let options = ReportOptions { self_intersections };
    let report = interruptible(py, threads, None, &|| {}, || {
        TopologyReport::with_options(mesh, &options)
    })?;
    // A mesher's output must be closed and manifold: say so when it is not. (A mesh from
    // elsewhere is only reported on, as `solidkit check` does.)
    if !extra.as_object().is_none_or(|m| m.is_empty()) {
        warnings
            .extend(warnings::empty(&report).or_else(|| warnings::not_closed_manifold(&report)));
        if let Some(cell) = extra.get("cell").and_then(Value::as_f64) {
            warnings.extend(warnings::fragments(&report, cell));
        }
    }
    let mut v = serde_json::to_value(&report).map_err(errors::other)?;
    if let (Value::Object(map), Value::Object(more)) = (&mut v, extra) {
        for (k, x) in more {
            map.insert(k.clone(), x.clone());
        }
    }
    if let Value::Object(map) = &mut v {
        map.insert("warnings".into(), Value::from(warnings));
    }
    py.import("json")?.call_method1("loads", (v.to_string(),))
}

#[pymethods]
impl PyMesh {
    /// A mesh from an N × 3 vertex array and an M × 3 array of vertex indices (copied).
    #[new]
    fn new(
        py: Python<'_>,
        vertices: PyArrayLike2<'_, f64, AllowTypeChange>,
        faces: PyArrayLike2<'_, i64, AllowTypeChange>,
    ) -> PyResult<PyMesh> {
        let mesh = indexed_from_arrays(py, &vertices, &faces)?;
        PyMesh::from_indexed(py, mesh, Vec::new(), Value::Object(Default::default()))
    }

    /// Vertex positions, N × 3 float64 (read-only).
    #[getter]
    fn vertices(&self, py: Python<'_>) -> Py<PyArray2<f64>> {
        self.vertices.clone_ref(py)
    }

    /// Triangles as vertex indices, M × 3 int64 (read-only).
    #[getter]
    fn faces(&self, py: Python<'_>) -> Py<PyArray2<i64>> {
        self.faces.clone_ref(py)
    }

    /// The triangles' colours from the tree's `color` nodes, M × 4 uint8 (red, green, blue,
    /// alpha; uncoloured triangles get the default `#f9d72cff`), or None when the tree had none.
    #[getter]
    fn face_colors<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyArray2<u8>>>> {
        let Some(c) = &self.colors else {
            return Ok(None);
        };
        let flat: Vec<u8> = (0..self.mesh.triangles.len())
            .flat_map(|t| c.color_or(t, DEFAULT_COLOR))
            .collect();
        let n = self.mesh.triangles.len();
        Ok(Some(frozen(PyArray1::from_vec(py, flat).reshape([n, 4])?)?))
    }

    /// What may be wrong or missing in this mesh (open operands, refinement stopped by a
    /// limit, ...), one line each.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    /// The topology report as a dict with the stable keys of `solidkit mesh --json` (closed,
    /// manifold, oriented, shells, genus, volume, area, bbox, ...), including `warnings` and,
    /// for a mesh made by `Solid.mesh`, what the mesher did (resolution, cells, refinement).
    #[pyo3(signature = (*, self_intersections = true, threads = None))]
    fn report<'py>(
        &self,
        py: Python<'py>,
        self_intersections: bool,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        report_dict(
            py,
            &self.mesh,
            self_intersections,
            threads,
            self.warnings.clone(),
            &self.info,
        )
    }

    /// Writes the mesh; the format follows the extension (.stl, .obj, .ply, .off, .3mf, .glb).
    /// 3MF, PLY, GLB and OFF carry `face_colors` when there are any (`colors=False`: none). The
    /// file is replaced atomically.
    #[pyo3(signature = (path, *, colors = true))]
    fn save(&self, py: Python<'_>, path: PathBuf, colors: bool) -> PyResult<()> {
        let c = self.colors.as_ref().filter(|_| colors);
        py.detach(|| write_colored_mesh_with(&path, &self.mesh, c, &WriteOptions::default()))
            .map_err(errors::io)
    }

    /// A `trimesh.Trimesh` with the same arrays (needs the trimesh package).
    fn to_trimesh<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let trimesh = py.import("trimesh")?;
        let kw = PyDict::new(py);
        kw.set_item("vertices", self.vertices.bind(py))?;
        kw.set_item("faces", self.faces.bind(py))?;
        kw.set_item("process", false)?;
        trimesh.getattr("Trimesh")?.call((), Some(&kw))
    }

    /// A `manifold3d.Manifold` of this mesh (needs the manifold3d package; positions become
    /// float32 as manifold3d stores them).
    fn to_manifold<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let m3d = py.import("manifold3d")?;
        let np = py.import("numpy")?;
        let kw = PyDict::new(py);
        kw.set_item(
            "vert_properties",
            np.call_method1("asarray", (self.vertices.bind(py), "float32"))?,
        )?;
        kw.set_item(
            "tri_verts",
            np.call_method1("asarray", (self.faces.bind(py), "uint32"))?,
        )?;
        let mesh = m3d.getattr("Mesh")?.call((), Some(&kw))?;
        m3d.getattr("Manifold")?.call1((mesh,))
    }

    /// The mesh of a `trimesh.Trimesh` (arrays copied).
    #[staticmethod]
    fn from_trimesh(py: Python<'_>, mesh: &Bound<'_, PyAny>) -> PyResult<PyMesh> {
        let v = mesh.getattr("vertices")?;
        let f = mesh.getattr("faces")?;
        PyMesh::new(py, v.extract()?, f.extract()?)
    }

    /// The mesh of a `manifold3d.Manifold` or `manifold3d.Mesh` (its first three vertex
    /// properties are the positions).
    #[staticmethod]
    fn from_manifold(py: Python<'_>, manifold: &Bound<'_, PyAny>) -> PyResult<PyMesh> {
        let mesh = if manifold.hasattr("to_mesh")? {
            manifold.call_method0("to_mesh")?
        } else {
            manifold.clone()
        };
        let props = mesh.getattr("vert_properties")?;
        let v = props.get_item((
            pyo3::types::PySlice::full(py),
            pyo3::types::PySlice::new(py, 0, 3, 1),
        ))?;
        let f = mesh.getattr("tri_verts")?;
        PyMesh::new(py, v.extract()?, f.extract()?)
    }

    fn __len__(&self) -> usize {
        self.mesh.triangles.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "Mesh({} vertices, {} faces)",
            self.mesh.positions.len(),
            self.mesh.triangles.len()
        )
    }
}

/// Adds the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyMesh>()
}
