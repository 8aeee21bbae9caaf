//! Dense sample grids: the field's value at every sample of a [`GridSpec`].

use super::sign::{LONE_ZERO, resolve_lone, settle, settle_field};
use crate::grid::GridSpec;
use glam::DVec3;
use rayon::prelude::*;
use solidkit_kernel::{Evaluator, Field};

/// Field values at every sample of a grid, in single precision (what the batch evaluator
/// produces; vertex interpolation is done in double precision from these values).
#[derive(Debug, Clone)]
pub struct SampleGrid {
    /// The grid.
    pub spec: GridSpec,
    /// Values, x fastest, then y, then z.
    pub values: Vec<f32>,
}

impl SampleGrid {
    /// Samples `field` at every grid point, one z-slice per parallel task.
    pub fn sample(field: &impl Field, spec: GridSpec) -> Self {
        let [sx, sy, _] = spec.samples();
        let mut values = vec![0.0f32; spec.sample_count()];
        values
            .par_chunks_mut(sx * sy)
            .enumerate()
            .for_each(|(k, slice)| {
                let mut row = vec![DVec3::ZERO; sx];
                let mut row_values = vec![0.0; sx];
                for (j, out) in slice.chunks_mut(sx).enumerate() {
                    for (i, p) in row.iter_mut().enumerate() {
                        *p = spec.point(i, j, k);
                    }
                    field.values(&row, &mut row_values);
                    for (i, (o, v)) in out.iter_mut().zip(&row_values).enumerate() {
                        let [x, y, z] = [0, 1, 2].map(|a| spec.coordinate(a, [i, j, k][a]));
                        *o = settle_field(field, x, y, z, *v as f32);
                    }
                }
            });
        Self::settled(spec, values)
    }

    /// Samples a lowered solid (any [`Evaluator`], usually a `Program`) at every grid point with
    /// the full evaluator (the dense path: no pruning), one z-slice per parallel task.
    pub fn sample_program<E: Evaluator>(program: &E, spec: GridSpec) -> Self {
        let [sx, sy, _] = spec.samples();
        let mut values = vec![0.0f32; spec.sample_count()];
        values
            .par_chunks_mut(sx * sy)
            .enumerate()
            .for_each(|(k, slice)| {
                let mut scratch = E::BatchScratch::default();
                let x: Vec<f32> = (0..sx).map(|i| spec.coordinate(0, i)).collect();
                let z = vec![spec.coordinate(2, k); sx];
                let mut y = vec![0f32; sx];
                let mut slots = E::ZeroScratch::default();
                for (j, out) in slice.chunks_mut(sx).enumerate() {
                    y.fill(spec.coordinate(1, j));
                    program.eval_many(&x, &y, &z, out, &mut scratch);
                    for (i, v) in out.iter_mut().enumerate() {
                        *v = settle(x[i], y[i], z[i], *v, |p| program.zero_side(p, &mut slots));
                    }
                }
            });
        Self::settled(spec, values)
    }

    /// The grid of `values` sampled and settled but for the lone zeros, which it settles from
    /// their lattice neighbours ([`resolve_lone`]).
    fn settled(spec: GridSpec, mut values: Vec<f32>) -> Self {
        let lone: Vec<usize> = values
            .par_iter()
            .enumerate()
            .filter(|(_, v)| **v == LONE_ZERO)
            .map(|(i, _)| i)
            .collect();
        let samples = spec.samples();
        // Every neighbour lies in the grid, so `outer` is never asked.
        resolve_lone(&mut values, samples, [0; 3], samples, &lone, |_| f32::NAN);
        Self { spec, values }
    }

    /// Wraps values already computed (x fastest); `None` if the count does not match the grid.
    pub fn from_values(spec: GridSpec, values: Vec<f32>) -> Option<Self> {
        (values.len() == spec.sample_count()).then_some(Self { spec, values })
    }

    /// Value at sample `(i, j, k)`.
    pub fn at(&self, i: usize, j: usize, k: usize) -> f32 {
        self.values[self.spec.index(i, j, k)]
    }
}
