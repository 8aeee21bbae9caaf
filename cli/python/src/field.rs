//! `Solid.eval`: the signed field at many points, in parallel chunks. Single precision goes
//! through the meshers' batch evaluator (points converted to structure-of-arrays chunks that
//! stay in cache); double precision and gradients through the double-precision paths.

use crate::deinterleave::Coordinate;
use crate::recycle;
use crate::run::detached;
use numpy::{
    AllowTypeChange, PyArray1, PyArray2, PyArrayLike2, PyArrayMethods, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use rayon::prelude::*;
use solidkit_kernel::program::BatchScratch;
use solidkit_kernel::{Program, Solid};

/// Points per parallel task.
const CHUNK: usize = 1 << 16;

/// Evaluates `solid` at the rows of `points` (N × 3); single-precision values go into `out`
/// when given (a writable float32 array of N values, returned).
pub fn eval<'py>(
    py: Python<'py>,
    solid: &Solid,
    points: &Bound<'py, PyAny>,
    gradients: bool,
    double: bool,
    threads: Option<usize>,
    out: Option<Bound<'py, PyArray1<f32>>>,
) -> PyResult<Bound<'py, PyAny>> {
    if out.is_some() && (gradients || double) {
        return Err(PyValueError::new_err(
            "out= takes the single-precision values only (not with gradients or double)",
        ));
    }
    // float32 arrays feed the single-precision path as they are.
    if !gradients
        && !double
        && let Ok(p32) = points.cast::<PyArray2<f32>>()
    {
        let p32 = p32.readonly();
        check_shape(p32.shape())?;
        if p32.is_c_contiguous()
            && let Ok(flat) = p32.as_slice()
        {
            let program = py.detach(|| solid.compile());
            return single_out(py, &program, flat, threads, out);
        }
    }
    let points: PyArrayLike2<'py, f64, AllowTypeChange> = points.extract()?;
    let shape = points.shape();
    check_shape(shape)?;
    let n = shape[0];
    // A C-contiguous copy only when the caller's array is not one already.
    let owned;
    // (`as_slice` also takes Fortran order, which is not x, y, z per point.)
    let flat: &[f64] = match points.as_slice() {
        Ok(s) if points.is_c_contiguous() => s,
        _ => {
            owned = points.as_array().iter().copied().collect::<Vec<f64>>();
            &owned
        }
    };
    let program = py.detach(|| solid.compile());
    if !gradients && !double {
        return single_out(py, &program, flat, threads, out);
    }
    if gradients {
        let (values, grads) = detached(py, threads, || {
            let mut values = recycle::take::<f64>(n);
            let mut grads = recycle::take::<f64>(3 * n);
            values[..n]
                .par_chunks_mut(CHUNK)
                .zip(grads[..3 * n].par_chunks_mut(3 * CHUNK))
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
        let v = recycle::array(py, values, n)?;
        let g = recycle::array(py, grads, 3 * n)?.reshape([n, 3])?;
        return Ok(PyTuple::new(py, [v.into_any(), g.into_any()])?.into_any());
    }
    // Double precision, without gradients.
    let values = detached(py, threads, || {
        let mut values = recycle::take::<f64>(n);
        values[..n]
            .par_chunks_mut(CHUNK)
            .zip(flat.par_chunks(3 * CHUNK))
            .for_each_init(Default::default, |scratch, (v, p)| {
                for (o, c) in v.iter_mut().zip(p.chunks_exact(3)) {
                    *o = program.value_with(glam::DVec3::new(c[0], c[1], c[2]), scratch);
                }
            });
        values
    })?;
    Ok(recycle::array(py, values, n)?.into_any())
}

/// Single-precision values of `program` at `flat` into `out` (checked) or a new array.
fn single_out<'py, T: Coordinate>(
    py: Python<'py>,
    program: &Program,
    flat: &[T],
    threads: Option<usize>,
    out: Option<Bound<'py, PyArray1<f32>>>,
) -> PyResult<Bound<'py, PyAny>> {
    let Some(out) = out else {
        let n = flat.len() / 3;
        let values = detached(py, threads, || single(program, flat))?;
        return Ok(recycle::array(py, values, n)?.into_any());
    };
    {
        let mut rw = out
            .try_readwrite()
            .map_err(|e| PyValueError::new_err(format!("out: {e}")))?;
        let slice = rw
            .as_slice_mut()
            .map_err(|_| PyValueError::new_err("out must be a contiguous float32 array"))?;
        if slice.len() != flat.len() / 3 {
            return Err(PyValueError::new_err(format!(
                "out has {} values for {} points",
                slice.len(),
                flat.len() / 3
            )));
        }
        detached(py, threads, || single_into(program, flat, slice))?;
    }
    Ok(out.into_any())
}

/// Checks that an array is N × 3.
fn check_shape(shape: &[usize]) -> PyResult<()> {
    if shape.len() != 2 || shape[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "points must be an N x 3 array, got shape {shape:?}"
        )));
    }
    Ok(())
}

/// Single-precision values at the points of `flat` (x, y, z interleaved), split and rounded
/// into structure-of-arrays blocks of [`SUB`] points for the batch evaluator.
fn single<T: Coordinate>(program: &Program, flat: &[T]) -> Vec<f32> {
    let n = flat.len() / 3;
    let mut values = recycle::take::<f32>(n);
    single_into(program, flat, &mut values[..n]);
    values
}

/// [`single`] into `values` (one per point).
fn single_into<T: Coordinate>(program: &Program, flat: &[T], values: &mut [f32]) {
    values
        .par_chunks_mut(CHUNK)
        .zip(flat.par_chunks(3 * CHUNK))
        .for_each_init(
            || {
                // One buffer for x, y and z, the three arrays a cache line apart beyond
                // 4 KiB multiples: stores to x[i], y[i], z[i] at addresses equal modulo 4 KiB
                // stall on the loads of the next point (4K aliasing), which tripled the cost.
                (BatchScratch::new(program), vec![0.0f32; 3 * SUB + 32])
            },
            |(scratch, buf), (v, p)| {
                let (x, rest) = buf.split_at_mut(SUB + 16);
                let (y, z) = rest.split_at_mut(SUB + 16);
                for (k, out) in v.chunks_mut(SUB).enumerate() {
                    let m = out.len();
                    let block = &p[3 * k * SUB..3 * (k * SUB + m)];
                    T::deinterleave(block, &mut x[..m], &mut y[..m], &mut z[..m]);
                    program.eval_many(&x[..m], &y[..m], &z[..m], out, scratch);
                }
            },
        );
}

/// Points per block of [`single`]: the block, its coordinate arrays and the evaluator's
/// registers stay in L1, and the input streams at a steady pace the hardware prefetcher follows
/// (1024-point blocks, and software prefetches of the next blocks, were 15–50% slower with
/// float64 input on this project's AMD machines, and no faster on an Intel one).
const SUB: usize = 256;
