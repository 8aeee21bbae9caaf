//! Edge crossings on the real field: where a sign-changing grid edge meets the surface, and the
//! unit normal there from the field gradient.
//!
//! Starts from the linear interpolation of the two samples and takes [`STEPS`] safeguarded Newton
//! steps along the edge (the derivative along the edge is the gradient's component), keeping a
//! bracket from the sample signs and bisecting whenever a step leaves it. All crossings of a block
//! are refined together, one batched evaluation per step ([`Evaluator::values_gradients`]).

use super::certify::CROSSING_MARGIN;
use glam::DVec3;
use solidkit_kernel::Evaluator;

/// Field evaluations per crossing (the last one gives the normal at the final point).
pub(crate) const STEPS: usize = 3;

/// One sign-changing edge: from `a` (sample value `fa`) to `b` (`fb`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct EdgeQuery {
    pub a: DVec3,
    pub b: DVec3,
    pub fa: f32,
    pub fb: f32,
}

/// Buffers of the batched search.
#[derive(Default)]
pub(crate) struct CrossingScratch {
    t: Vec<f64>,
    lo: Vec<f64>,
    hi: Vec<f64>,
    points: Vec<DVec3>,
    values: Vec<f64>,
    gradients: Vec<DVec3>,
}

/// Crossing points and unit normals (pointing to positive values) of `queries`, appended to `out`.
/// Points stay [`CROSSING_MARGIN`] (of the edge length) away from the samples, so every crossing
/// lies strictly inside its edge (a surface through a sample is moved that far).
pub(crate) fn refine<F: Evaluator>(
    field: &F,
    queries: &[EdgeQuery],
    out: &mut Vec<(DVec3, DVec3)>,
    s: &mut CrossingScratch,
    fs: &mut F::GradientScratch,
) {
    let n = queries.len();
    s.t.clear();
    s.lo.clear();
    s.hi.clear();
    for q in queries {
        let (fa, fb) = (q.fa as f64, q.fb as f64);
        let t = fa / (fa - fb);
        s.t.push(if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.5
        });
        s.lo.push(0.0);
        s.hi.push(1.0);
    }
    s.points.resize(n, DVec3::ZERO);
    s.values.resize(n, 0.0);
    s.gradients.resize(n, DVec3::ZERO);
    for step in 0..STEPS {
        for (k, q) in queries.iter().enumerate() {
            s.points[k] = q.a + (q.b - q.a) * s.t[k];
        }
        field.values_gradients(&s.points, &mut s.values, &mut s.gradients, fs);
        if step + 1 == STEPS {
            break;
        }
        for (k, q) in queries.iter().enumerate() {
            let (v, t) = (s.values[k], s.t[k]);
            if v == 0.0 {
                continue; // on the surface already
            }
            // The bracket keeps the end with the lower sample's sign at `lo`.
            if (v < 0.0) == (q.fa < 0.0) {
                s.lo[k] = t;
            } else {
                s.hi[k] = t;
            }
            let slope = s.gradients[k].dot(q.b - q.a);
            let next = t - v / slope;
            s.t[k] = if next.is_finite() && next >= s.lo[k] && next <= s.hi[k] {
                next
            } else {
                0.5 * (s.lo[k] + s.hi[k])
            };
        }
    }
    out.extend(queries.iter().enumerate().map(|(k, q)| {
        let g = s.gradients[k];
        let len = g.length();
        let normal = if len > 1e-300 && len.is_finite() {
            g / len
        } else {
            // No usable gradient: the edge direction, from inside to outside.
            let d = (q.b - q.a).normalize();
            if q.fa < 0.0 { d } else { -d }
        };
        let t = s.t[k].clamp(CROSSING_MARGIN, 1.0 - CROSSING_MARGIN);
        (q.a + (q.b - q.a) * t, normal)
    }));
}
