//! `Solid`: a CSG tree, built with the same primitives, Booleans, blends and transforms as Rust
//! and Rhai (operators `|`, `&`, `-`), read from JSON text, or loaded from a `.json`, `.rhai` or
//! `.csg` file through the front ends (files it names confined to its folder and the `allow`
//! folders, as on the command line).

use crate::errors;
use glam::DVec3;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use solidkit_frontends::csg::Facets;
use solidkit_frontends::load::{Format, LoadOptions, load_path, load_str};
use solidkit_kernel::Solid;
use solidkit_kernel::json;
use solidkit_kernel::primitive::{Gyroid, Primitive};
use std::path::PathBuf;

/// A solid: a CSG tree evaluated as a signed field (negative inside).
#[pyclass(module = "solidkit", name = "Solid", frozen)]
#[derive(Clone)]
pub struct PySolid {
    /// The tree.
    pub solid: Solid,
    /// What the front end warned about when the solid was loaded (parts skipped the way
    /// OpenSCAD skips them), one line each.
    pub warnings: Vec<String>,
}

/// A number or three numbers (`cube(1)` or `cube([1, 2, 3])`).
#[derive(FromPyObject)]
pub enum NumOrVec {
    /// The same on every axis.
    Num(f64),
    /// Per axis.
    Vec([f64; 3]),
}

impl NumOrVec {
    fn vec(&self) -> DVec3 {
        match self {
            NumOrVec::Num(v) => DVec3::splat(*v),
            NumOrVec::Vec(v) => DVec3::from(*v),
        }
    }
}

impl PySolid {
    /// A solid without warnings.
    pub fn new(solid: Solid) -> Self {
        PySolid {
            solid,
            warnings: Vec::new(),
        }
    }

    /// Checks every parameter of the tree (a ValueError naming the node otherwise).
    pub fn validated(&self) -> PyResult<&Solid> {
        self.solid
            .validate()
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        Ok(&self.solid)
    }

    /// A new solid made from this one, keeping its warnings.
    fn derive(&self, solid: Solid) -> Self {
        PySolid {
            solid,
            warnings: self.warnings.clone(),
        }
    }
}

/// A leaf, its parameters checked now.
fn leaf(solid: Solid) -> PyResult<PySolid> {
    let s = PySolid::new(solid);
    s.validated()?;
    Ok(s)
}

/// The solids of `*args`, warnings of all kept.
fn collect(args: &Bound<'_, PyTuple>, what: &str) -> PyResult<(Vec<Solid>, Vec<String>)> {
    let mut out = Vec::with_capacity(args.len());
    let mut warnings = Vec::new();
    for (i, a) in args.iter().enumerate() {
        let s = a.cast::<PySolid>().map_err(|_| {
            PyValueError::new_err(format!(
                "{what}: argument {} is a {}, not a Solid",
                i + 1,
                a.get_type().name().map_or("?".into(), |n| n.to_string())
            ))
        })?;
        let s = s.get();
        out.push(s.solid.clone());
        warnings.extend(s.warnings.iter().cloned());
    }
    Ok((out, warnings))
}

/// A sphere of `radius` at the origin.
#[pyfunction]
fn sphere(radius: f64) -> PyResult<PySolid> {
    leaf(Solid::sphere(radius))
}

/// An axis-aligned box centred at the origin: `size` is one edge length or three.
#[pyfunction]
fn cube(size: NumOrVec) -> PyResult<PySolid> {
    leaf(Solid::cuboid(size.vec()))
}

/// Same as `cube`.
#[pyfunction(name = "box")]
fn box_(size: NumOrVec) -> PyResult<PySolid> {
    leaf(Solid::cuboid(size.vec()))
}

/// Same as `cube`.
#[pyfunction]
fn cuboid(size: NumOrVec) -> PyResult<PySolid> {
    leaf(Solid::cuboid(size.vec()))
}

/// A cylinder along z, centred at the origin.
#[pyfunction]
fn cylinder(radius: f64, height: f64) -> PyResult<PySolid> {
    leaf(Solid::cylinder(radius, height))
}

/// A truncated cone along z, centred at the origin (radii at the bottom and the top).
#[pyfunction]
fn cone(bottom: f64, top: f64, height: f64) -> PyResult<PySolid> {
    leaf(Solid::cone(bottom, top, height))
}

/// A torus around z, centred at the origin.
#[pyfunction]
fn torus(major_radius: f64, minor_radius: f64) -> PyResult<PySolid> {
    leaf(Solid::torus(major_radius, minor_radius))
}

/// The half-space `normal · p <= offset` (unbounded: mesh it with `bounds`).
#[pyfunction]
fn plane(normal: [f64; 3], offset: f64) -> PyResult<PySolid> {
    leaf(Solid::half_space(DVec3::from(normal), offset))
}

/// The gyroid sheet of the given thickness (unbounded: intersect it or mesh with `bounds`).
#[pyfunction]
fn gyroid(thickness: f64) -> PyResult<PySolid> {
    leaf(Solid::primitive(Primitive::Gyroid(Gyroid { thickness })))
}

/// The union of any number of solids (none: the empty solid).
#[pyfunction(signature = (*solids))]
fn union(solids: &Bound<'_, PyTuple>) -> PyResult<PySolid> {
    let (s, warnings) = collect(solids, "union")?;
    Ok(PySolid {
        solid: Solid::union_all(s),
        warnings,
    })
}

/// The intersection of any number of solids.
#[pyfunction(signature = (*solids))]
fn intersection(solids: &Bound<'_, PyTuple>) -> PyResult<PySolid> {
    let (s, warnings) = collect(solids, "intersection")?;
    Ok(PySolid {
        solid: Solid::intersection_all(s),
        warnings,
    })
}

/// The first solid minus all the others.
#[pyfunction(signature = (base, *cutters))]
fn difference(base: &PySolid, cutters: &Bound<'_, PyTuple>) -> PyResult<PySolid> {
    let (c, mut warnings) = collect(cutters, "difference")?;
    warnings.splice(0..0, base.warnings.iter().cloned());
    Ok(PySolid {
        solid: Solid::difference_all(base.solid.clone(), c),
        warnings,
    })
}

/// A smooth (rounded) union of the solids with blend `radius`.
#[pyfunction(signature = (*solids, radius))]
fn smooth_union(solids: &Bound<'_, PyTuple>, radius: f64) -> PyResult<PySolid> {
    let (s, warnings) = collect(solids, "smooth_union")?;
    blend(Solid::smooth_union_all(s, radius), warnings)
}

/// A smooth intersection of the solids with blend `radius`.
#[pyfunction(signature = (*solids, radius))]
fn smooth_intersection(solids: &Bound<'_, PyTuple>, radius: f64) -> PyResult<PySolid> {
    let (s, warnings) = collect(solids, "smooth_intersection")?;
    blend(Solid::smooth_intersection_all(s, radius), warnings)
}

/// The first solid smoothly minus the others, blend `radius`.
#[pyfunction(signature = (base, *cutters, radius))]
fn smooth_difference(
    base: &PySolid,
    cutters: &Bound<'_, PyTuple>,
    radius: f64,
) -> PyResult<PySolid> {
    let (c, mut warnings) = collect(cutters, "smooth_difference")?;
    warnings.splice(0..0, base.warnings.iter().cloned());
    blend(
        Solid::smooth_difference_all(base.solid.clone(), c, radius),
        warnings,
    )
}

fn blend(solid: Solid, warnings: Vec<String>) -> PyResult<PySolid> {
    let s = PySolid { solid, warnings };
    s.validated()?;
    Ok(s)
}

/// Load options from the keyword arguments of `load` and `from_json`.
fn options(
    facets: &str,
    allow: Option<Vec<PathBuf>>,
    base_dir: Option<PathBuf>,
) -> PyResult<LoadOptions> {
    let mut o = LoadOptions::default();
    o.facets = match facets {
        "exact" => Facets::Exact,
        "openscad" => Facets::OpenScad,
        other => {
            return Err(PyValueError::new_err(format!(
                "facets must be 'exact' or 'openscad', not {other:?}"
            )));
        }
    };
    o.allow = allow.unwrap_or_default();
    o.base_dir = base_dir;
    Ok(o)
}

/// Reads a solid from a `.json` tree, a `.rhai` script, an OpenSCAD `.csg` file or a `.scad`
/// file (through the installed OpenSCAD, with `defines` as its `-D name=value`), by extension;
/// in `.rhai` scripts each define is a constant (the value a Rhai literal).
/// Files it names must lie in its folder or in one of `allow`.
#[pyfunction(signature = (path, *, facets = "exact", allow = None, defines = None))]
fn load(
    py: Python<'_>,
    path: PathBuf,
    facets: &str,
    allow: Option<Vec<PathBuf>>,
    defines: Option<Vec<String>>,
) -> PyResult<PySolid> {
    let mut o = options(facets, allow, None)?;
    o.defines = defines.unwrap_or_default();
    let loaded = py.detach(|| load_path(&path, &o)).map_err(errors::load)?;
    let s = PySolid {
        solid: loaded.solid,
        warnings: loaded.warnings,
    };
    crate::warn::warn_all(py, &s.warnings)?;
    Ok(s)
}

/// A solid from the text of a JSON tree (a whole document or one node); files it names resolve
/// from `base_dir` (default: the current directory) and the `allow` folders.
#[pyfunction(signature = (text, *, base_dir = None, allow = None, name = "<json>"))]
fn from_json(
    py: Python<'_>,
    text: &str,
    base_dir: Option<PathBuf>,
    allow: Option<Vec<PathBuf>>,
    name: &str,
) -> PyResult<PySolid> {
    let o = options("exact", allow, base_dir)?;
    let loaded = py
        .detach(|| load_str(text, Format::Json, name, &o))
        .map_err(errors::load)?;
    Ok(PySolid::new(loaded.solid))
}

#[pymethods]
impl PySolid {
    /// Moved by `offset`.
    fn translate(&self, offset: [f64; 3]) -> PySolid {
        self.derive(self.solid.translate(DVec3::from(offset)))
    }

    /// Rotated by `degrees` about `axis` (through the origin).
    fn rotate(&self, axis: [f64; 3], degrees: f64) -> PySolid {
        self.derive(self.solid.rotate(DVec3::from(axis), degrees))
    }

    /// Scaled by one factor or three.
    fn scale(&self, factor: NumOrVec) -> PySolid {
        self.derive(self.solid.scale(factor.vec()))
    }

    /// Mirrored in the plane through the origin with this normal.
    fn mirror(&self, normal: [f64; 3]) -> PySolid {
        self.derive(self.solid.mirror(DVec3::from(normal)))
    }

    /// Transformed by a 3 × 4 row-major affine matrix.
    fn affine(&self, matrix: [[f64; 4]; 3]) -> PySolid {
        self.derive(self.solid.affine(matrix))
    }

    /// Grown by `distance` (shrunk when negative).
    fn offset(&self, distance: f64) -> PySolid {
        self.derive(self.solid.offset(distance))
    }

    /// A hollow shell of the given thickness around the surface.
    fn shell(&self, thickness: f64) -> PySolid {
        self.derive(self.solid.shell(thickness))
    }

    /// Painted: `color` a CSS/SVG name, `"#rrggbb[aa]"` or 3 or 4 numbers in 0..1; `alpha`
    /// replaces the alpha of a name or of 3 numbers. Geometry is unchanged; the innermost colour
    /// wins, and `Mesh.face_colors` and `Mesh.save` (3MF, PLY, GLB, OFF) carry it.
    #[pyo3(signature = (color, alpha = None))]
    fn color(&self, color: &Bound<'_, PyAny>, alpha: Option<f64>) -> PyResult<PySolid> {
        use solidkit_kernel::Rgba;
        let bad = || {
            pyo3::exceptions::PyValueError::new_err(
                "color: expected a colour name, \"#rrggbb\" or 3 or 4 numbers between 0 and 1",
            )
        };
        let c = if let Ok(s) = color.extract::<String>() {
            let c = Rgba::parse(&s).ok_or_else(|| {
                pyo3::exceptions::PyValueError::new_err(format!("color: unknown colour {s:?}"))
            })?;
            let hex_alpha = s.trim().starts_with('#') && matches!(s.trim().len(), 5 | 9);
            match alpha {
                Some(a) if !hex_alpha => c.with_alpha(a as f32),
                _ => c,
            }
        } else {
            let v: Vec<f64> = color.extract().map_err(|_| bad())?;
            match (v.as_slice(), alpha) {
                (&[r, g, b], a) => Rgba([r, g, b, a.unwrap_or(1.0)].map(|x| x as f32)),
                (&[r, g, b, a], _) => Rgba([r, g, b, a].map(|x| x as f32)),
                _ => return Err(bad()),
            }
        };
        if c.problem().is_some() {
            return Err(bad());
        }
        Ok(self.derive(self.solid.color(c)))
    }

    fn __or__(&self, other: &PySolid) -> PySolid {
        self.pair(other, self.solid.union(&other.solid))
    }

    fn __and__(&self, other: &PySolid) -> PySolid {
        self.pair(other, self.solid.intersection(&other.solid))
    }

    fn __sub__(&self, other: &PySolid) -> PySolid {
        self.pair(other, self.solid.difference(&other.solid))
    }

    /// The JSON tree document of this solid (`solidkit mesh` reads it back).
    fn to_json(&self) -> String {
        json::to_string(&self.solid)
    }

    /// The bounding box `((xmin, ymin, zmin), (xmax, ymax, zmax))`; infinite for unbounded solids.
    #[getter]
    fn bbox(&self) -> ([f64; 3], [f64; 3]) {
        let b = self.solid.bbox();
        (b.min.to_array(), b.max.to_array())
    }

    /// What the front end warned about when this solid (or a part of it) was loaded.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    /// The root node's kind, e.g. `"sphere"` or `"union"`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.solid.kind().name()
    }

    fn __repr__(&self) -> String {
        format!("Solid({})", self.solid.kind().name())
    }

    /// Values of the signed field at the points of an N × 3 array (negative inside): float32 from
    /// the meshers' single-precision batch evaluator, or float64 with `double=True`. With
    /// `gradients=True`, returns `(values, gradients)` in double precision (N and N × 3).
    /// Runs on `threads` threads (default: all cores) with the GIL released; `out`, a float32
    /// array of N values, receives the single-precision values instead of a new array.
    #[pyo3(signature = (points, *, gradients = false, double = false, threads = None, out = None))]
    fn eval<'py>(
        &self,
        py: Python<'py>,
        points: &Bound<'py, PyAny>,
        gradients: bool,
        double: bool,
        threads: Option<usize>,
        out: Option<Bound<'py, numpy::PyArray1<f32>>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        crate::field::eval(
            py,
            self.validated()?,
            points,
            gradients,
            double,
            threads,
            out,
        )
    }

    /// Meshes the solid: marching cubes (`method="mc"`, the default) or dual contouring (`"dc"`,
    /// optionally simplified to `tolerance`; the default with `target_error`), then, with
    /// `simplify=E` or `target_error=E`, edge collapses that keep the surface within `E` (model
    /// units) and the mesh closed, manifold and of the same genus, `resolution` cells along the longest side of its bounding box
    /// (or of `bounds`, `((xmin, ymin, zmin), (xmax, ymax, zmax))`, which also clips it), refined
    /// up to `refine` times finer where features are thinner than a cell. `progress(stage, done,
    /// total)` is called from this thread; Ctrl-C stops the run with KeyboardInterrupt.
    /// `method="polyhedral"` uses no grid: boxes, polyhedra, meshes and flat-quad height fields
    /// are combined by exact mesh Booleans (a cube is 12 triangles), and a part with no
    /// polyhedral form is meshed alone with `resolution` cells along its own longest side, with a
    /// warning.
    #[pyo3(signature = (resolution = 128, *, method = None, tolerance = None, bounds = None,
        refine = 32, max_memory = None, threads = None, progress = None, simplify = None,
        target_error = None))]
    #[allow(clippy::too_many_arguments)]
    fn mesh(
        &self,
        py: Python<'_>,
        resolution: usize,
        method: Option<&str>,
        tolerance: Option<f64>,
        bounds: Option<([f64; 3], [f64; 3])>,
        refine: usize,
        max_memory: Option<u64>,
        threads: Option<usize>,
        progress: Option<Bound<'_, PyAny>>,
        simplify: Option<f64>,
        target_error: Option<f64>,
    ) -> PyResult<crate::mesh::PyMesh> {
        let args = crate::meshing::MeshArgs {
            resolution,
            method,
            simplify,
            target_error,
            tolerance,
            bounds,
            refine,
            max_memory,
            threads,
            progress,
        };
        crate::meshing::mesh(py, self.validated()?, &self.warnings, args)
    }
}

impl PySolid {
    fn pair(&self, other: &PySolid, solid: Solid) -> PySolid {
        let mut warnings = self.warnings.clone();
        warnings.extend(other.warnings.iter().cloned());
        PySolid { solid, warnings }
    }
}

/// Adds the class and the builder functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PySolid>()?;
    m.add_function(wrap_pyfunction!(sphere, m)?)?;
    m.add_function(wrap_pyfunction!(cube, m)?)?;
    m.add_function(wrap_pyfunction!(box_, m)?)?;
    m.add_function(wrap_pyfunction!(cuboid, m)?)?;
    m.add_function(wrap_pyfunction!(cylinder, m)?)?;
    m.add_function(wrap_pyfunction!(cone, m)?)?;
    m.add_function(wrap_pyfunction!(torus, m)?)?;
    m.add_function(wrap_pyfunction!(plane, m)?)?;
    m.add_function(wrap_pyfunction!(gyroid, m)?)?;
    m.add_function(wrap_pyfunction!(union, m)?)?;
    m.add_function(wrap_pyfunction!(intersection, m)?)?;
    m.add_function(wrap_pyfunction!(difference, m)?)?;
    m.add_function(wrap_pyfunction!(smooth_union, m)?)?;
    m.add_function(wrap_pyfunction!(smooth_intersection, m)?)?;
    m.add_function(wrap_pyfunction!(smooth_difference, m)?)?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(from_json, m)?)?;
    Ok(())
}
