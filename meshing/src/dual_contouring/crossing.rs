//! Edge crossings on the real field: where a sign-changing grid edge meets the surface, and the
//! unit normal there from the field gradient.
//!
//! Starts from the linear interpolation of the two samples and takes [`STEPS`] safeguarded Newton
//! steps along the edge (the derivative along the edge is the gradient's component), keeping a
//! bracket from the sample signs and bisecting whenever a step leaves it. All crossings of a block
//! are refined together, one batched evaluation per step ([`Evaluator::values_gradients`]).
//!
//! A block's program is pruned for the whole block, which leaves long programs where many
//! primitives meet (a faceted sphere keeps every face plane within a few cells). For those,
//! [`refine_grouped`] prunes once more for each small group of cells and searches that group's
//! crossings with the shorter program. A pruned program gives the same values, bit for bit, in
//! its box, so the crossings are exactly those of the block's program.

use super::certify::CROSSING_MARGIN;
use glam::DVec3;
use solidkit_kernel::{Aabb, Evaluator};

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

/// Programs at least this long are pruned again per group of crossings ([`refine_grouped`]);
/// shorter ones cost less to evaluate than to prune.
pub(crate) const GROUP_PRUNE_LEN: usize = 32;

/// Buffers of the grouped search.
#[derive(Default)]
pub(crate) struct GroupScratch {
    order: Vec<u32>,
    queries: Vec<EdgeQuery>,
    found: Vec<(DVec3, DVec3)>,
}

/// [`refine`] with `field` pruned again for each group of queries (`group[k]` is query `k`'s
/// group; a group's box is the box of its edges). Same results as [`refine`] on `field`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn refine_grouped<F: Evaluator>(
    field: &F,
    queries: &[EdgeQuery],
    group: &[u32],
    out: &mut Vec<(DVec3, DVec3)>,
    s: &mut CrossingScratch,
    g: &mut GroupScratch,
    fs: &mut F::GradientScratch,
    is: &mut F::IntervalScratch,
) {
    let base = out.len();
    out.resize(base + queries.len(), (DVec3::ZERO, DVec3::ZERO));
    g.order.clear();
    g.order.extend(0..queries.len() as u32);
    g.order.sort_unstable_by_key(|&k| (group[k as usize], k));
    for run in g
        .order
        .chunk_by(|&a, &b| group[a as usize] == group[b as usize])
    {
        g.queries.clear();
        g.queries.extend(run.iter().map(|&k| queries[k as usize]));
        let mut b = Aabb::new(g.queries[0].a, g.queries[0].a);
        for q in &g.queries {
            b = Aabb::new(b.min.min(q.a).min(q.b), b.max.max(q.a).max(q.b));
        }
        field.interval_with(&b, is);
        let pruned = field.prune(is);
        g.found.clear();
        match &pruned {
            Some(p) => refine(p, &g.queries, &mut g.found, s, fs),
            None => refine(field, &g.queries, &mut g.found, s, fs),
        }
        for (&k, &c) in run.iter().zip(&g.found) {
            out[base + k as usize] = c;
        }
    }
}
