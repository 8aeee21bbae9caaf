//! Curves given by formulas: `C(u) = (x(u), y(u), z(u))` for `u ∈ [u0, u1]`, each coordinate a
//! formula in `u` in the grammar of the `expr` node (see
//! [`parse`](crate::primitive::expr::parse)), e.g. the rose `x = cos(2*u)*cos(u)`,
//! `y = cos(2*u)*sin(u)`. Derivatives are exact (forward-mode differentiation of the formula,
//! twice nested for the second derivative), not finite differences. A formula curve has no
//! control points: it is not one of the [`Curve`](super::Curve) kinds (sweep paths and rails
//! need control polygons for their bounds); the `curve` command and profiles flatten it by
//! sampling.

use super::CurveError;
use super::piece::Jet;
use crate::Interval;
use crate::primitive::expr::code::{Dual, Iv, Num, Op, run};
use crate::primitive::expr::parse::parse_in;
use glam::DVec3;

/// A curve `(x(u), y(u), z(u))` over `[u0, u1]`.
#[derive(Debug, Clone, PartialEq)]
pub struct FormulaCurve {
    formulas: [String; 3],
    code: [Vec<Op>; 3],
    domain: (f64, f64),
}

type D2 = Dual<Dual<f64>>;

impl FormulaCurve {
    /// Parses the three coordinate formulas (in the variable `u`) over `[u0, u1]`.
    pub fn new(formulas: [&str; 3], domain: (f64, f64)) -> Result<FormulaCurve, CurveError> {
        let (u0, u1) = domain;
        if !(u0.is_finite() && u1.is_finite() && u0 < u1) {
            return Err(CurveError::Domain);
        }
        let keys = ["x", "y", "z"];
        let mut code: [Vec<Op>; 3] = Default::default();
        for (k, f) in formulas.iter().enumerate() {
            code[k] = parse_in(f, ["u", "", ""]).map_err(|e| CurveError::Formula {
                parameter: keys[k],
                message: e.to_string(),
            })?;
        }
        Ok(FormulaCurve {
            formulas: formulas.map(str::to_string),
            code,
            domain,
        })
    }

    /// The closed plane curve `ρ(u)·(cos u, sin u, 0)` for `u ∈ [0, 2π]` from the formula `rho`
    /// in `u` (the radius at the angle `u`): the radial equation of a profile.
    pub fn radial(rho: &str) -> Result<FormulaCurve, CurveError> {
        let r = parse_in(rho, ["u", "", ""]).map_err(|e| CurveError::Formula {
            parameter: "rho",
            message: e.to_string(),
        })?;
        let times = |trig: Op| {
            let mut c = r.clone();
            c.extend([Op::X, trig, Op::Mul]);
            c
        };
        Ok(FormulaCurve {
            formulas: [
                format!("({rho})*cos(u)"),
                format!("({rho})*sin(u)"),
                "0".to_string(),
            ],
            code: [times(Op::Cos), times(Op::Sin), vec![Op::Const(0.0)]],
            domain: (0.0, std::f64::consts::TAU),
        })
    }

    /// The formulas `[x, y, z]` as given.
    pub fn formulas(&self) -> &[String; 3] {
        &self.formulas
    }

    /// The parameter interval `(u0, u1)`.
    pub fn domain(&self) -> (f64, f64) {
        self.domain
    }

    /// The point at `u` (clamped to the domain).
    pub fn point(&self, u: f64) -> DVec3 {
        let u = u.clamp(self.domain.0, self.domain.1);
        let mut stack = Vec::new();
        let c = |k: usize, stack: &mut Vec<f64>| run(&self.code[k], [u, 0.0, 0.0], stack);
        DVec3::new(c(0, &mut stack), c(1, &mut stack), c(2, &mut stack))
    }

    /// A bound of the speed `|C'(u)|` over `[a, b]` from interval arithmetic on the formulas'
    /// derivatives (forward-mode differentiation over intervals, widened by 10⁻¹² for rounding);
    /// `None` where the derivative's range is unbounded or may be NaN.
    pub fn speed_bound(&self, a: f64, b: f64) -> Option<f64> {
        let (a, b) = (
            a.clamp(self.domain.0, self.domain.1),
            b.clamp(self.domain.0, self.domain.1),
        );
        let var = Dual {
            v: Iv(
                Interval {
                    lo: a.min(b),
                    hi: a.max(b),
                },
                false,
            ),
            d: [Iv::constant(1.0), Iv::constant(0.0), Iv::constant(0.0)],
        };
        let args = [var, Dual::constant(0.0), Dual::constant(0.0)];
        let mut stack = Vec::new();
        let mut sum = 0.0;
        for code in &self.code {
            let r: Dual<Iv> = run(code, args, &mut stack);
            let Iv(d, nan) = r.d[0];
            if nan || !(d.lo.is_finite() && d.hi.is_finite()) {
                return None;
            }
            let m = d.lo.abs().max(d.hi.abs());
            sum += m * m;
        }
        Some(sum.sqrt() * (1.0 + 1e-12))
    }

    /// Point, first and second derivative at `u` (clamped to the domain).
    pub fn jet(&self, u: f64) -> Jet {
        let u = u.clamp(self.domain.0, self.domain.1);
        let zero = Dual::<f64>::constant(0.0);
        let var = D2 {
            v: Dual {
                v: u,
                d: [1.0, 0.0, 0.0],
            },
            d: [Dual::constant(1.0), zero, zero],
        };
        let args = [var, D2::constant(0.0), D2::constant(0.0)];
        let mut stack = Vec::new();
        let r: [D2; 3] = [0, 1, 2].map(|k| run(&self.code[k], args, &mut stack));
        Jet {
            point: DVec3::new(r[0].v.v, r[1].v.v, r[2].v.v),
            d1: DVec3::new(r[0].d[0].v, r[1].d[0].v, r[2].d[0].v),
            d2: DVec3::new(r[0].d[0].d[0], r[1].d[0].d[0], r[2].d[0].d[0]),
        }
    }
}
