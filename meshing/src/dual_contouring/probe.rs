//! Field values at the diagonal midpoints of folded quads (which diagonal keeps a crease,
//! [`super::contour`]), evaluated in batches: a block's quads ask about points in the cells around
//! their edges, each answered by the evaluator of the block holding that cell (valid there), so
//! the points are grouped by that block and each group is one batched call.

use glam::DVec3;
use solidkit_kernel::Evaluator;
use std::sync::Arc;

/// Field values for choosing quad diagonals.
pub(crate) trait Probe: Sync {
    /// Buffers of one worker.
    type Scratch: Default + Send;
    /// The field at `points` (all in cells of block `block`), appended to `out`.
    fn values(&self, block: usize, points: &[DVec3], out: &mut Vec<f64>, s: &mut Self::Scratch);
}

/// Probes with each block's own (pruned) evaluator, in single precision (the values only rank
/// two midpoints): `self.0[b]` is block `b`'s.
pub(crate) struct ProgramProbe<'a, E>(pub &'a [Arc<E>]);

/// Buffers of [`ProgramProbe`].
#[derive(Default)]
pub(crate) struct ProgramScratch<S> {
    xyz: [Vec<f32>; 3],
    out: Vec<f32>,
    batch: S,
}

impl<E: Evaluator> Probe for ProgramProbe<'_, E> {
    type Scratch = ProgramScratch<E::BatchScratch>;

    fn values(&self, block: usize, points: &[DVec3], out: &mut Vec<f64>, s: &mut Self::Scratch) {
        for (axis, c) in s.xyz.iter_mut().enumerate() {
            c.clear();
            c.extend(points.iter().map(|p| p[axis] as f32));
        }
        s.out.clear();
        s.out.resize(points.len(), 0.0);
        let [x, y, z] = &s.xyz;
        self.0[block].eval_many(x, y, z, &mut s.out, &mut s.batch);
        out.extend(s.out.iter().map(|&v| f64::from(v)));
    }
}

/// Probes one field everywhere (in double precision).
pub(crate) struct FieldProbe<'a, F>(pub &'a F);

impl<F: Evaluator> Probe for FieldProbe<'_, F> {
    type Scratch = (F::GradientScratch, Vec<f64>, Vec<DVec3>);

    fn values(&self, _: usize, points: &[DVec3], out: &mut Vec<f64>, s: &mut Self::Scratch) {
        let (scratch, values, gradients) = s;
        values.resize(points.len(), 0.0);
        gradients.resize(points.len(), DVec3::ZERO);
        self.0.values_gradients(points, values, gradients, scratch);
        out.extend_from_slice(&values[..points.len()]);
    }
}

/// Buffers of [`evaluate`].
#[derive(Default)]
pub(crate) struct BatchScratch<S> {
    order: Vec<u32>,
    points: Vec<DVec3>,
    values: Vec<f64>,
    probe: S,
}

/// The field at each request's point (`(block, point)`), grouped by block, written to `out` in
/// request order.
pub(crate) fn evaluate<P: Probe>(
    probe: &P,
    requests: &[(usize, DVec3)],
    out: &mut Vec<f64>,
    s: &mut BatchScratch<P::Scratch>,
) {
    out.clear();
    out.resize(requests.len(), 0.0);
    s.order.clear();
    s.order.extend(0..requests.len() as u32);
    // Stable, so each block's requests stay in request order (most are the asking block's).
    s.order.sort_by_key(|&k| requests[k as usize].0);
    for run in s
        .order
        .chunk_by(|&a, &b| requests[a as usize].0 == requests[b as usize].0)
    {
        s.points.clear();
        s.points.extend(run.iter().map(|&k| requests[k as usize].1));
        s.values.clear();
        let block = requests[run[0] as usize].0;
        probe.values(block, &s.points, &mut s.values, &mut s.probe);
        for (&k, &v) in run.iter().zip(&s.values) {
            out[k as usize] = v;
        }
    }
}
