//! `Solid.eval`: the signed field at many points, in parallel chunks. Single precision goes
//! through the meshers' batch evaluator (points converted to structure-of-arrays chunks that
//! stay in cache); double precision and gradients through the double-precision paths.

use crate::run::interruptible;
use numpy::{AllowTypeChange, PyArray1, PyArrayLike2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use rayon::prelude::*;
use solidkit_kernel::Solid;
use solidkit_kernel::program::BatchScratch;

/// Points per chunk: big enough to amortise the batch set-up, small enough to stay in L2.
const CHUNK: usize = 4096;

/// Evaluates `solid` at the rows of `points` (N × 3).
pub fn eval<'py>(
    py: Python<'py>,
    solid: &Solid,
    points: PyArrayLike2<'py, f64, AllowTypeChange>,
    gradients: bool,
    double: bool,
    threads: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    let shape = points.shape();
    if shape[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "points must be an N x 3 array, got {} x {}",
            shape[0], shape[1]
        )));
    }
    let n = shape[0];
    // A C-contiguous copy only when the caller's array is not one already.
    let owned;
    let flat: &[f64] = match points.as_slice() {
        Ok(s) => s,
        Err(_) => {
            owned = points.as_array().iter().copied().collect::<Vec<f64>>();
            &owned
        }
    };
    let program = py.detach(|| solid.compile());
    let never = || {};
    if gradients {
        let (values, grads) = interruptible(py, threads, None, &never, || {
            let mut values = vec![0.0f64; n];
            let mut grads = vec![0.0f64; 3 * n];
            values
                .par_chunks_mut(CHUNK)
                .zip(grads.par_chunks_mut(3 * CHUNK))
                .zip(flat.par_chunks(3 * CHUNK))
                .for_each_init(
                    || (Default::default(), Vec::new(), Vec::new()),
                    |(scratch, pts, gs), ((v, g), p)| {
                        pts.clear();
                        pts.extend(
                            p.chunks_exact(3)
                                .map(|c| glam::DVec3::new(c[0], c[1], c[2])),
                        );
                        gs.resize(pts.len(), glam::DVec3::ZERO);
                        program.values_gradients(pts, v, gs, scratch);
                        for (o, d) in g.chunks_exact_mut(3).zip(gs.iter()) {
                            o.copy_from_slice(&d.to_array());
                        }
                    },
                );
            (values, grads)
        })?;
        let v = PyArray1::from_vec(py, values);
        let g = PyArray1::from_vec(py, grads).reshape([n, 3])?;
        return Ok(PyTuple::new(py, [v.into_any(), g.into_any()])?.into_any());
    }
    if double {
        let values = interruptible(py, threads, None, &never, || {
            let mut values = vec![0.0f64; n];
            values
                .par_chunks_mut(CHUNK)
                .zip(flat.par_chunks(3 * CHUNK))
                .for_each_init(Default::default, |scratch, (v, p)| {
                    for (o, c) in v.iter_mut().zip(p.chunks_exact(3)) {
                        *o = program.value_with(glam::DVec3::new(c[0], c[1], c[2]), scratch);
                    }
                });
            values
        })?;
        return Ok(PyArray1::from_vec(py, values).into_any());
    }
    let values = interruptible(py, threads, None, &never, || {
        let mut values = vec![0.0f32; n];
        values
            .par_chunks_mut(CHUNK)
            .zip(flat.par_chunks(3 * CHUNK))
            .for_each_init(
                || {
                    (
                        BatchScratch::new(&program),
                        vec![0.0f32; CHUNK],
                        vec![0.0f32; CHUNK],
                        vec![0.0f32; CHUNK],
                    )
                },
                |(scratch, x, y, z), (v, p)| {
                    for (i, c) in p.chunks_exact(3).enumerate() {
                        x[i] = c[0] as f32;
                        y[i] = c[1] as f32;
                        z[i] = c[2] as f32;
                    }
                    program.eval_many(x, y, z, v, scratch);
                },
            );
        values
    })?;
    Ok(PyArray1::from_vec(py, values).into_any())
}
