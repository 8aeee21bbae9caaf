//! `Solid.mesh`: the library's meshing pipeline with the command line's defaults (memory budget,
//! refinement, resolution range), interruptible, its warnings passed to Python's `warnings`.

use crate::mesh::PyMesh;
use crate::run::{ProgressSlot, interruptible};
use glam::DVec3;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use solidkit_kernel::{Aabb, Solid};
use solidkit_meshing::colors::assign;
use solidkit_meshing::octree::{CancelToken, Progress};
use solidkit_meshing::pipeline::limits::{MAX_RESOLUTION, default_max_memory};
use solidkit_meshing::pipeline::{Domain, MeshOptions, Method, PipelineError, Prepared};
use solidkit_meshing::polyhedral::{NotPolyhedral, from_solid_gridding};
use solidkit_meshing::refine::RefineOptions;
use std::sync::Arc;

/// The keyword arguments of `Solid.mesh`.
pub struct MeshArgs<'a, 'py> {
    /// Cells along the longest side.
    pub resolution: usize,
    /// `"mc"`, `"dc"` or `"polyhedral"` (default: `"dc"` with `target_error`, else `"mc"`).
    pub method: Option<&'a str>,
    /// Edge-collapse simplification within this distance (model units) after meshing.
    pub simplify: Option<f64>,
    /// Dual contouring then simplification within this distance (`mesh --target-error`).
    pub target_error: Option<f64>,
    /// Dual contouring's simplification tolerance.
    pub tolerance: Option<f64>,
    /// Clipping bounds.
    pub bounds: Option<([f64; 3], [f64; 3])>,
    /// Most refinement factor (1: none).
    pub refine: usize,
    /// Memory budget in bytes (default: half the machine's memory).
    pub max_memory: Option<u64>,
    /// Worker threads (default: all cores).
    pub threads: Option<usize>,
    /// `progress(stage, done, total)`.
    pub progress: Option<Bound<'py, PyAny>>,
}

impl MeshArgs<'_, '_> {
    /// The method asked for, or the default (`"dc"` with `target_error`, else `"mc"`).
    fn method_name(&self) -> &str {
        self.method.unwrap_or(if self.target_error.is_some() {
            "dc"
        } else {
            "mc"
        })
    }
}

/// The pipeline's options for `a`, range-checked like the command line's.
fn options(a: &MeshArgs<'_, '_>) -> PyResult<MeshOptions> {
    if !(1..=MAX_RESOLUTION).contains(&a.resolution) {
        return Err(PyValueError::new_err(format!(
            "resolution must be 1 to {MAX_RESOLUTION}, got {}",
            a.resolution
        )));
    }
    if !(1..=32).contains(&a.refine) || !a.refine.is_power_of_two() {
        return Err(PyValueError::new_err(format!(
            "refine must be 1, 2, 4, 8, 16 or 32, got {}",
            a.refine
        )));
    }
    let method = match a.method_name() {
        "mc" => Method::Mc,
        "dc" => Method::Dc,
        other => {
            return Err(PyValueError::new_err(format!(
                "method must be 'mc', 'dc' or 'polyhedral', not {other:?}"
            )));
        }
    };
    for (name, e) in [("simplify", a.simplify), ("target_error", a.target_error)] {
        if let Some(e) = e
            && !(e.is_finite() && e > 0.0)
        {
            return Err(PyValueError::new_err(format!(
                "{name} must be a positive number, got {e}"
            )));
        }
    }
    if let Some(t) = a.tolerance
        && !(t.is_finite() && t > 0.0)
    {
        return Err(PyValueError::new_err(format!(
            "tolerance must be a positive number, got {t}"
        )));
    }
    let domain = match a.bounds {
        None => Domain::Solid,
        Some((lo, hi)) => {
            let (lo, hi) = (DVec3::from(lo), DVec3::from(hi));
            if !(lo.is_finite() && hi.is_finite() && lo.cmplt(hi).all()) {
                return Err(PyValueError::new_err(
                    "bounds must be ((xmin, ymin, zmin), (xmax, ymax, zmax)) with finite min < max",
                ));
            }
            Domain::Clip(Aabb::new(lo, hi))
        }
    };
    let refine = RefineOptions {
        max_factor: a.refine,
        ..RefineOptions::default()
    };
    Ok(MeshOptions::new(a.resolution)
        .method(method)
        .domain(domain)
        .tolerance(a.tolerance)
        .simplify(a.target_error.or(a.simplify))
        .refine(refine)
        .max_memory(Some(a.max_memory.unwrap_or_else(default_max_memory))))
}

/// Meshes `solid` (checked) as `a` asks; `loaded` are the warnings its front end gave, kept
/// first in the mesh's warnings (they were issued when it was loaded).
pub fn mesh(
    py: Python<'_>,
    solid: &Solid,
    loaded: &[String],
    a: MeshArgs<'_, '_>,
) -> PyResult<PyMesh> {
    if a.method == Some("polyhedral") {
        return polyhedral(py, solid, loaded, &a);
    }
    let slot = Arc::new(ProgressSlot::default());
    let token = CancelToken::new();
    let mut options = options(&a)?.cancel(token.clone());
    if a.progress.is_some() {
        let sink = Arc::clone(&slot);
        options = options.progress(Arc::new(move |p: Progress| {
            sink.set(p.stage, p.done, p.total)
        }));
    }
    let cancel = move || token.cancel();
    let progress = a.progress.as_ref().map(|cb| (cb, slot.as_ref()));
    let result = interruptible(py, a.threads, progress, &cancel, || {
        let prepared = Prepared::new(solid, &options)?;
        let meshed = prepared.mesh()?;
        let colors = meshed.face_colors(solid);
        Ok::<_, PipelineError>((prepared.warnings, (meshed, colors)))
    })?;
    let (mut warnings, (meshed, colors)) = result.map_err(|e| match e {
        PipelineError::Unbounded => crate::errors::meshing(
            "the solid is unbounded; pass bounds=((xmin, ymin, zmin), (xmax, ymax, zmax))",
        ),
        e => crate::errors::meshing(e),
    })?;
    warnings.splice(0..0, loaded.iter().cloned());
    warnings.extend(meshed.warnings.iter().cloned());
    let warnings: Vec<String> = warnings
        .iter()
        .map(|w| crate::errors::pythonic(w))
        .collect();
    crate::warn::warn_all(py, &warnings[loaded.len()..])?;
    let asked = crate::mesh::Asked {
        resolution: a.resolution,
        method: a.method_name(),
        simplify: a.target_error.or(a.simplify),
        target_error: a.target_error,
    };
    PyMesh::from_meshed(py, meshed, colors, warnings, asked)
}

/// `method="polyhedral"`: the tree's polyhedra combined by mesh Booleans, no grid (the command
/// line's `mesh --method polyhedral`); a part with no polyhedral form is meshed alone on a grid of
/// `resolution` cells along its own longest side, with a warning.
fn polyhedral(
    py: Python<'_>,
    solid: &Solid,
    loaded: &[String],
    a: &MeshArgs<'_, '_>,
) -> PyResult<PyMesh> {
    let grid_only = [
        ("tolerance", a.tolerance.is_some()),
        ("simplify", a.simplify.is_some()),
        ("target_error", a.target_error.is_some()),
        ("bounds", a.bounds.is_some()),
    ];
    if let Some((name, _)) = grid_only.iter().find(|(_, on)| *on) {
        return Err(PyValueError::new_err(format!(
            "{name} needs a grid: it does not go with method='polyhedral'"
        )));
    }
    if !(1..=MAX_RESOLUTION).contains(&a.resolution) {
        return Err(PyValueError::new_err(format!(
            "resolution must be 1 to {MAX_RESOLUTION}, got {}",
            a.resolution
        )));
    }
    let resolution = a.resolution;
    let (mesh, colors, found) = py
        .detach(|| {
            let (p, found) = from_solid_gridding(solid, Some(resolution))?;
            let mesh = p.to_mesh();
            let (lo, hi) = p.bounds().unwrap_or_default();
            let colors = assign(solid, &mesh, 1e-6 * (hi - lo).length() + 1e-12);
            Ok::<_, NotPolyhedral>((mesh, colors, found))
        })
        .map_err(crate::errors::meshing)?;
    let found: Vec<String> = found.iter().map(|w| crate::errors::pythonic(w)).collect();
    crate::warn::warn_all(py, &found)?;
    let info = serde_json::json!({
        "resolution": a.resolution,
        "method": "polyhedral",
        "colors": colors.as_ref().map_or(0, |c| c.used()),
    });
    let mut warnings = loaded.to_vec();
    warnings.extend(found);
    let mut out = PyMesh::from_indexed(py, mesh, warnings, info)?;
    out.colors = colors;
    Ok(out)
}
