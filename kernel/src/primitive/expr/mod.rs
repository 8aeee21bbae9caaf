//! A solid given by a formula: `{p in bounds : g(p) ≤ 0}` for a formula `g(x, y, z)` such as
//! `x^2 + y^2 - z` or `sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)` (the grammar is in
//! [`parse`]), cut by an axis-aligned box `bounds`.
//!
//! **The field** is `f(p) = max(g(clamp(p)), d_box(p))`, with `clamp` the nearest point of the box
//! and `d_box` the exact signed distance to it: inside the box the zero set is exactly `g`'s (and
//! the box's faces where `g < 0` reaches them), outside `f ≥ d_box > 0`. It is **not a distance**
//! unless `g` is one: the Lipschitz bound reported is `max(1, L_g)`, with `L_g` a bound of `|∇g|`
//! over the box from interval arithmetic on the derivatives (infinite where that cannot bound it,
//! e.g. `sqrt` near 0: the bound is then unknown, which only the conformance tests read).
//! What holds for every formula: the interval over a box contains every value the point
//! evaluators give there (so octree culling and pruning are sound), the solid lies in `bounds`
//! and `{f ≤ level}` in `bounds` grown by `level` (so offsets stay inside their boxes), and the
//! gradient is the formula's where it is differentiable. Offsets and blends of a formula that is
//! not a distance move its surface by field units, not lengths.
//!
//! Operations are total (see [`code`]): no point is undefined; NaN counts as outside.

pub mod code;
pub mod parse;
#[cfg(test)]
mod tests;

use super::{Cuboid, PrimitiveError, Shape, faithful};
use crate::{Aabb, Interval};
use code::{Dual, Iv, Num, Op, run};
use glam::DVec3;

/// Largest magnitude of a formula's value: results are clamped to ±`LIMIT`, and NaN is `LIMIT`.
pub const LIMIT: f64 = 1e30;

/// A formula solid cut by a box.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    formula: String,
    bounds: Aabb,
    code: Vec<Op>,
    lipschitz: f64,
}

/// A formula or box that makes no solid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExprError {
    /// The formula does not parse.
    #[error("formula: {0}")]
    Parse(#[from] parse::ParseError),
    /// The box is not a finite box with positive sides.
    #[error("{0}")]
    Bounds(PrimitiveError),
}

/// The formula's final value: NaN is outside, everything within ±[`LIMIT`].
fn total(v: f64) -> f64 {
    if v.is_nan() {
        LIMIT
    } else {
        v.clamp(-LIMIT, LIMIT)
    }
}

impl Expr {
    /// Parses `formula` and checks `bounds` (finite, each side positive).
    pub fn new(formula: &str, bounds: Aabb) -> Result<Self, ExprError> {
        check_bounds(&bounds).map_err(ExprError::Bounds)?;
        let code = parse::parse(formula)?;
        let mut e = Expr {
            formula: formula.to_string(),
            bounds,
            code,
            lipschitz: f64::INFINITY,
        };
        e.lipschitz = e.gradient_bound().max(1.0);
        Ok(e)
    }

    /// The formula as given.
    pub fn formula(&self) -> &str {
        &self.formula
    }

    /// The box that cuts the solid.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    fn cuboid(&self) -> Cuboid {
        Cuboid {
            size: self.bounds.size(),
        }
    }

    fn clamp(&self, p: DVec3) -> DVec3 {
        p.clamp(self.bounds.min, self.bounds.max)
    }

    /// The formula's value at a point of the box.
    fn g(&self, q: DVec3, stack: &mut Vec<f64>) -> f64 {
        total(run(&self.code, q.to_array(), stack))
    }

    /// A bound of `|∇g|` over the box (infinite when interval arithmetic finds none).
    fn gradient_bound(&self) -> f64 {
        let b = self.bounds;
        let var = |i: usize| {
            let mut d = [Iv::constant(0.0); 3];
            d[i] = Iv::constant(1.0);
            Dual {
                v: Iv(Interval::new(b.min[i], b.max[i]), false),
                d,
            }
        };
        let g = run(&self.code, [var(0), var(1), var(2)], &mut Vec::new());
        let sq: f64 =
            g.d.iter()
                .map(|d| d.0.lo.abs().max(d.0.hi.abs()).powi(2))
                .sum();
        if sq.is_finite() {
            sq.sqrt()
        } else {
            f64::INFINITY
        }
    }
}

/// Checks that `b` is a finite box with positive sides within the faithful range.
fn check_bounds(b: &Aabb) -> Result<(), PrimitiveError> {
    let bad = |problem| {
        Err(PrimitiveError {
            parameter: "bounds",
            problem,
        })
    };
    for i in 0..3 {
        if !(b.min[i].is_finite() && b.max[i].is_finite()) {
            return bad("expected finite corners");
        }
        if !faithful(b.min[i]) || !faithful(b.max[i]) {
            return bad("expected coordinates of magnitude at most 1e30 (and 0 or at least 1e-30)");
        }
        if b.max[i] <= b.min[i] {
            return bad("expected the second corner above the first on every axis");
        }
    }
    Ok(())
}

impl Shape for Expr {
    fn value(&self, p: DVec3) -> f64 {
        let g = self.g(self.clamp(p), &mut Vec::with_capacity(16));
        g.max(self.cuboid().value(p - self.bounds.center()))
    }

    fn gradient(&self, p: DVec3) -> DVec3 {
        let q = self.clamp(p);
        let c = self.bounds.center();
        let g = self.g(q, &mut Vec::with_capacity(16));
        if g < self.cuboid().value(p - c) {
            return self.cuboid().gradient(p - c);
        }
        let var = |i: usize| {
            let mut d = [0.0; 3];
            d[i] = 1.0;
            Dual { v: q[i], d }
        };
        let r = run(&self.code, [var(0), var(1), var(2)], &mut Vec::new());
        let d = DVec3::from_array(r.d);
        // Along an axis where p lies past the box the clamped formula does not change.
        let moving = DVec3::select(p.cmpeq(q), DVec3::ONE, DVec3::ZERO);
        let d = d * moving;
        if r.v.is_finite() && d.is_finite() {
            d
        } else {
            DVec3::ZERO
        }
    }

    fn interval(&self, b: &Aabb) -> Interval {
        let q = Aabb::new(self.clamp(b.min), self.clamp(b.max));
        let var = |i: usize| Iv(Interval::new(q.min[i], q.max[i]), false);
        let Iv(g, nan) = run(
            &self.code,
            [var(0), var(1), var(2)],
            &mut Vec::with_capacity(16),
        );
        // The total function's range (NaN is the outside value), widened for the rounding of
        // the point evaluators.
        let (lo, hi) = (total_lo(g.lo), if nan { LIMIT } else { total_hi(g.hi) });
        let pad = |v: f64| v.abs() * 1e-12 + 1e-300;
        let g = Interval::new(lo - pad(lo), hi + pad(hi));
        let c = self.bounds.center();
        let shifted = Aabb::new(b.min - c, b.max - c);
        g.max(self.cuboid().interval(&shifted))
    }

    fn bbox(&self) -> Aabb {
        self.bounds
    }

    fn validate(&self) -> Result<(), PrimitiveError> {
        check_bounds(&self.bounds)
    }

    fn lipschitz(&self) -> f64 {
        self.lipschitz
    }

    fn values_f32(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32]) {
        let mut stack = Vec::with_capacity(16);
        let c = self.bounds.center();
        let cuboid = self.cuboid();
        for i in 0..out.len() {
            let p = DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64);
            let g = self.g(self.clamp(p), &mut stack);
            out[i] = g.max(cuboid.value(p - c)) as f32;
        }
    }
}

/// The lower end of the total function's range (NaN means the whole line).
fn total_lo(lo: f64) -> f64 {
    if lo.is_nan() {
        -LIMIT
    } else {
        lo.clamp(-LIMIT, LIMIT)
    }
}

/// The upper end of the total function's range.
fn total_hi(hi: f64) -> f64 {
    if hi.is_nan() {
        LIMIT
    } else {
        hi.clamp(-LIMIT, LIMIT)
    }
}
