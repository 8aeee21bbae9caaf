//! Result buffers recycled between `Solid.eval` calls.
//!
//! A fresh array of 10⁷ values is 40 MB the kernel must map and zero page by page on first
//! write (about 1.5 ns a value here, as long as evaluating a sphere), and the C library returns
//! blocks that large to the kernel as soon as they are freed. So the values are written into a
//! Rust buffer owned by a small Python object (the array's base); when the last array using it
//! goes away, the buffer returns to a pool instead of the kernel, and the next call of a similar
//! size writes into memory that is already mapped. The pool is bounded: buffers of at least
//! [`MIN_BYTES`], at most [`MAX_BUFFERS`] of each element type and [`MAX_BYTES`] in all.

use numpy::ndarray::ArrayView1;
use numpy::{Element, PyArray1};
use pyo3::prelude::*;
use std::sync::Mutex;

/// Smaller buffers are left to the allocator, which reuses them itself.
const MIN_BYTES: usize = 4 << 20;
/// Buffers kept per element type (values and gradients of two calls).
const MAX_BUFFERS: usize = 4;
/// Bytes kept per element type.
const MAX_BYTES: usize = 512 << 20;

/// An element type whose buffers are pooled.
pub trait Pooled: Element + Copy + Default + Send + 'static {
    /// The pool of this type.
    fn pool() -> &'static Mutex<Vec<Vec<Self>>>;
    /// The buffer as the owner object stores it.
    fn store(v: Vec<Self>) -> Storage;
    /// The buffer of an owner object of this type.
    fn slice(s: &Storage) -> &[Self];
}

static F32: Mutex<Vec<Vec<f32>>> = Mutex::new(Vec::new());
static F64: Mutex<Vec<Vec<f64>>> = Mutex::new(Vec::new());

impl Pooled for f32 {
    fn pool() -> &'static Mutex<Vec<Vec<f32>>> {
        &F32
    }
    fn store(v: Vec<f32>) -> Storage {
        Storage::F32(v)
    }
    fn slice(s: &Storage) -> &[f32] {
        match s {
            Storage::F32(v) => v,
            Storage::F64(_) => &[],
        }
    }
}

impl Pooled for f64 {
    fn pool() -> &'static Mutex<Vec<Vec<f64>>> {
        &F64
    }
    fn store(v: Vec<f64>) -> Storage {
        Storage::F64(v)
    }
    fn slice(s: &Storage) -> &[f64] {
        match s {
            Storage::F64(v) => v,
            Storage::F32(_) => &[],
        }
    }
}

/// A buffer of one of the pooled types.
pub enum Storage {
    /// Single-precision values.
    F32(Vec<f32>),
    /// Double-precision values or gradients.
    F64(Vec<f64>),
}

/// The owner of a recycled buffer: the base object of the arrays [`array`] returns.
#[pyclass(frozen, module = "solidkit._solidkit")]
pub struct Recycled {
    storage: Storage,
}

impl Drop for Recycled {
    fn drop(&mut self) {
        match &mut self.storage {
            Storage::F32(v) => give_back(std::mem::take(v)),
            Storage::F64(v) => give_back(std::mem::take(v)),
        }
    }
}

/// A buffer of at least `n` elements (its contents are stale values or zeros): a pooled one
/// between `n` and `2n` long when there is one, else a new one.
pub fn take<T: Pooled>(n: usize) -> Vec<T> {
    if n * size_of::<T>() >= MIN_BYTES {
        let mut pool = T::pool().lock().unwrap_or_else(|e| e.into_inner());
        if let Some(i) = pool.iter().position(|v| v.len() >= n && v.len() <= 2 * n) {
            return pool.swap_remove(i);
        }
    }
    vec![T::default(); n]
}

/// Keeps `v` for a later [`take`] when the pool has room, else frees it.
fn give_back<T: Pooled>(v: Vec<T>) {
    if v.len() * size_of::<T>() < MIN_BYTES {
        return;
    }
    let mut pool = T::pool().lock().unwrap_or_else(|e| e.into_inner());
    let held: usize = pool.iter().map(|b| b.len() * size_of::<T>()).sum();
    if pool.len() < MAX_BUFFERS && held + v.len() * size_of::<T>() <= MAX_BYTES {
        pool.push(v);
    }
}

/// The first `n` elements of `v` as a numpy array whose base object owns `v`.
pub fn array<T: Pooled>(py: Python<'_>, v: Vec<T>, n: usize) -> PyResult<Bound<'_, PyArray1<T>>> {
    assert!(v.len() >= n, "a buffer of {} for {n} values", v.len());
    let owner = Bound::new(
        py,
        Recycled {
            storage: T::store(v),
        },
    )?;
    let view = ArrayView1::from(&T::slice(&owner.get().storage)[..n]);
    // SAFETY: the array's memory is the owner's buffer, which the owner (set as the array's
    // base, so alive as long as the array) never reallocates or changes; it goes back to the
    // pool only when the owner is dropped.
    Ok(unsafe { PyArray1::borrow_from_array(&view, owner.clone().into_any()) })
}
