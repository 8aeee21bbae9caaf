//! Formula surfaces: `p(u, v) = (x(u, v), y(u, v), z(u, v))` from three formulas in `u` and `v`
//! (the grammar of [`crate::primitive::expr::parse`] with the variables `u`, `v`), or a graph
//! `z = f(u, v)` with `x = u`, `y = v` when only `z` is given, over the parameter rectangle
//! `[u₀, u₁] × [v₀, v₁]`. Derivatives up to second order are exact (forward-mode duals nested
//! twice), so curvatures come from the fundamental forms without finite differences.

use super::derivs::SurfaceDerivatives;
use super::error::SurfaceError;
use crate::primitive::expr::code::{Dual, Op, run};
use crate::primitive::expr::parse::parse_in;
use glam::DVec3;

/// A parametric surface given by formulas.
#[derive(Debug, Clone, PartialEq)]
pub struct FormulaSurface {
    /// The formulas of x, y, z as given (`None` for x and y in the graph form).
    formulas: [Option<String>; 3],
    code: [Vec<Op>; 3],
    u: [f64; 2],
    v: [f64; 2],
}

type D2 = Dual<Dual<f64>>;

/// `a` as a twice-differentiable variable number `k` (0: u, 1: v).
fn variable(a: f64, k: usize) -> D2 {
    let zero = Dual {
        v: 0.0,
        d: [0.0; 3],
    };
    let mut inner = Dual { v: a, d: [0.0; 3] };
    inner.d[k] = 1.0;
    let mut outer = D2 {
        v: inner,
        d: [zero; 3],
    };
    outer.d[k] = Dual {
        v: 1.0,
        d: [0.0; 3],
    };
    outer
}

impl FormulaSurface {
    /// The surface `(x, y, z)(u, v)` over `u ∈ [u₀, u₁]`, `v ∈ [v₀, v₁]`; `x` and `y` both `None`
    /// for the graph `z = f(u, v)`. Fails on a formula that does not parse (its key and column)
    /// or an empty or non-finite range.
    pub fn new(
        x: Option<&str>,
        y: Option<&str>,
        z: &str,
        u: [f64; 2],
        v: [f64; 2],
    ) -> Result<Self, SurfaceError> {
        for (key, r) in [("u", u), ("v", v)] {
            if !(r[0].is_finite() && r[1].is_finite() && r[0] < r[1]) {
                return Err(SurfaceError::invalid(
                    key,
                    "expected [min, max] with finite min below max",
                ));
            }
        }
        if x.is_some() != y.is_some() {
            return Err(SurfaceError::invalid(
                if x.is_some() { "y" } else { "x" },
                "give x, y and z, or only z (the graph z = f(u, v))",
            ));
        }
        let parse = |key: &'static str, text: &str| {
            parse_in(text, ["u", "v", ""])
                .map_err(|e| SurfaceError::invalid(key, format!("formula: {e}")))
        };
        let code = [
            match x {
                Some(t) => parse("x", t)?,
                None => vec![Op::X],
            },
            match y {
                Some(t) => parse("y", t)?,
                None => vec![Op::Y],
            },
            parse("z", z)?,
        ];
        Ok(FormulaSurface {
            formulas: [
                x.map(str::to_owned),
                y.map(str::to_owned),
                Some(z.to_owned()),
            ],
            code,
            u,
            v,
        })
    }

    /// The formulas of x, y, z as given (`None` for x and y of a graph).
    pub fn formulas(&self) -> &[Option<String>; 3] {
        &self.formulas
    }

    /// The parameter ranges `([u₀, u₁], [v₀, v₁])`.
    pub fn ranges(&self) -> ([f64; 2], [f64; 2]) {
        (self.u, self.v)
    }

    /// The point and its derivatives with respect to `u` and `v` at the parameters `(u, v)`.
    pub fn derivatives_at(&self, u: f64, v: f64) -> SurfaceDerivatives {
        let mut stack = Vec::new();
        let args = [variable(u, 0), variable(v, 1), variable(0.0, 2)];
        let mut out = [[0.0; 6]; 3];
        for (c, code) in self.code.iter().enumerate() {
            let r = run(code, args, &mut stack);
            out[c] = [
                r.v.v,
                r.v.d[0],
                r.v.d[1],
                r.d[0].d[0],
                r.d[0].d[1],
                r.d[1].d[1],
            ];
        }
        let col = |k: usize| DVec3::new(out[0][k], out[1][k], out[2][k]);
        SurfaceDerivatives {
            p: col(0),
            pu: col(1),
            pv: col(2),
            puu: col(3),
            puv: col(4),
            pvv: col(5),
        }
    }

    /// The point and its derivatives with respect to `(s, t)` of the unit square.
    pub fn derivatives(&self, s: f64, t: f64) -> SurfaceDerivatives {
        let (a, b) = (self.u[1] - self.u[0], self.v[1] - self.v[0]);
        self.derivatives_at(self.u[0] + s * a, self.v[0] + t * b)
            .rescaled(a, b)
    }
}
