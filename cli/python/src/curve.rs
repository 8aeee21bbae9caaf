//! `Curve`: a curve of the JSON format (every kind of `docs/json-format.md`'s "Curves") read by the
//! kernel's reader, evaluated from Python: points and derivatives, domain, arc length, the de
//! Casteljau split of the Bézier piece at a parameter, and polylines as read-only numpy arrays.

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use solidkit_kernel::curve::flatten::uniform_params;
use solidkit_kernel::curve::{BezierPiece, Parametric};

/// A curve (Bézier, Hermite, B-spline, NURBS, interpolating, cubic_through, composite, formula).
#[pyclass(name = "Curve", module = "solidkit", frozen)]
pub struct PyCurve(Parametric);

type P3 = (f64, f64, f64);

fn t3(p: glam::DVec3) -> P3 {
    (p.x, p.y, p.z)
}

/// `points` as a read-only N × 3 array.
fn array<'py>(py: Python<'py>, points: &[glam::DVec3]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = points.iter().flat_map(|p| p.to_array()).collect();
    let a = PyArray1::from_vec(py, flat).reshape([points.len(), 3])?;
    let kw = PyDict::new(py);
    kw.set_item("write", false)?;
    a.call_method("setflags", (), Some(&kw))?;
    Ok(a)
}

fn piece<'py>(py: Python<'py>, p: &BezierPiece) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let points: Vec<glam::DVec3> = p.projected().collect();
    d.set_item("points", array(py, &points)?)?;
    d.set_item("weights", p.points.iter().map(|q| q.w).collect::<Vec<_>>())?;
    d.set_item("interval", (p.t0, p.t1))?;
    Ok(d)
}

impl PyCurve {
    fn param(&self, u: f64, what: &str) -> PyResult<f64> {
        let (t0, t1) = self.0.domain();
        if u.is_finite() && u >= t0 && u <= t1 {
            Ok(u)
        } else {
            Err(PyValueError::new_err(format!(
                "{what}: {u} is outside the curve's domain [{t0}, {t1}]"
            )))
        }
    }
}

#[pymethods]
impl PyCurve {
    /// The kind, e.g. `"bezier"` or `"formula"`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.0.name()
    }

    /// The parameter interval `(t0, t1)`.
    #[getter]
    fn domain(&self) -> (f64, f64) {
        self.0.domain()
    }

    /// True when the curve ends where it starts.
    #[getter]
    fn closed(&self) -> bool {
        self.0.is_closed()
    }

    /// The point at `u`.
    fn point(&self, u: f64) -> PyResult<P3> {
        Ok(t3(self.0.point(self.param(u, "point")?)))
    }

    /// The first derivative at `u`.
    fn derivative(&self, u: f64) -> PyResult<P3> {
        Ok(t3(self.0.jet(self.param(u, "derivative")?).d1))
    }

    /// The second derivative at `u`.
    fn second_derivative(&self, u: f64) -> PyResult<P3> {
        Ok(t3(self.0.jet(self.param(u, "second_derivative")?).d2))
    }

    /// The unit tangent at `u` (zero where the derivative is zero).
    fn tangent(&self, u: f64) -> PyResult<P3> {
        Ok(t3(self
            .0
            .jet(self.param(u, "tangent")?)
            .d1
            .normalize_or_zero()))
    }

    /// The arc length.
    fn length(&self) -> f64 {
        self.0.arc_length()
    }

    /// The de Casteljau split of the Bézier piece holding `u`: `{"left", "right"}`, each with
    /// `points` (N × 3), `weights` and `interval`; and `piece`, its index.
    fn split<'py>(&self, py: Python<'py>, u: f64) -> PyResult<Bound<'py, PyDict>> {
        let u = self.param(u, "split")?;
        let s = self.0.split(u).ok_or_else(|| {
            PyValueError::new_err("split: a formula curve has no control points to split")
        })?;
        let d = PyDict::new(py);
        d.set_item("left", piece(py, &s.left)?)?;
        d.set_item("right", piece(py, &s.right)?)?;
        d.set_item("piece", s.piece)?;
        Ok(d)
    }

    /// The vertices (N × 3) of a polyline within `chord_error` of the curve (certified for curves
    /// with control points, estimated from samples for formula curves).
    fn polyline<'py>(
        &self,
        py: Python<'py>,
        chord_error: f64,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let line = py
            .detach(|| self.0.polyline(chord_error))
            .map_err(|e| PyValueError::new_err(format!("polyline: {e}")))?;
        array(py, &line.points)
    }

    /// `n` points (N × 3) at equally spaced parameters, ends included.
    fn samples<'py>(&self, py: Python<'py>, n: usize) -> PyResult<Bound<'py, PyArray2<f64>>> {
        if !(2..=10_000_000).contains(&n) {
            return Err(PyValueError::new_err(format!(
                "samples: expected 2 to 10000000 points, found {n}"
            )));
        }
        let points: Vec<_> = uniform_params(self.0.domain(), n)
            .into_iter()
            .map(|u| self.0.point(u))
            .collect();
        array(py, &points)
    }

    fn __repr__(&self) -> String {
        let (t0, t1) = self.0.domain();
        format!("Curve({}, domain=({t0}, {t1}))", self.0.name())
    }
}

/// A curve from the JSON text of one curve object.
#[pyfunction]
fn curve_from_json(text: &str) -> PyResult<PyCurve> {
    match solidkit_kernel::json::curve_from_str(text) {
        Ok(c) => Ok(PyCurve(c)),
        Err(solidkit_kernel::KernelError::Json { message, .. }) => {
            Err(PyValueError::new_err(format!("curve: {message}")))
        }
        Err(e) => Err(PyValueError::new_err(format!("curve: {e}"))),
    }
}

/// Adds the class and `curve_from_json` to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyCurve>()?;
    m.add_function(wrap_pyfunction!(curve_from_json, m)?)?;
    Ok(())
}
