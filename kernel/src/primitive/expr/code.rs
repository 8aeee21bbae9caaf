//! Postfix formula code and its evaluation in one generic stack machine over four number kinds:
//! `f64` (values), [`Iv`] (sound ranges over a box), and [`Dual`] of either (values with their
//! gradient; gradient ranges for the Lipschitz bound).
//!
//! Every operation is total, so every point has a value: `sqrt` of a negative number is 0,
//! `log` of a number below the smallest positive normal is the log of that normal, a power with
//! a non-integer exponent reads a negative base as 0; a NaN left at the end (e.g. `0/0`) counts as
//! outside and the result is clamped to ±[`super::LIMIT`]. The interval versions contain every
//! value of these total functions and carry a flag for "may be NaN here", which the final range
//! turns into its top reaching the "outside" value.

use crate::Interval;
use crate::primitive::{cos_interval, sin_interval};

/// One instruction of the postfix code.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Op {
    /// Push x.
    X,
    /// Push y.
    Y,
    /// Push z.
    Z,
    /// Push a constant.
    Const(f64),
    /// a + b.
    Add,
    /// a − b.
    Sub,
    /// a · b.
    Mul,
    /// a / b.
    Div,
    /// A power with a constant exponent; replaced by `Powi` or `Powf` while parsing.
    Pow,
    /// −a.
    Neg,
    /// |a|.
    Abs,
    /// sin a.
    Sin,
    /// cos a.
    Cos,
    /// exp a.
    Exp,
    /// ln max(a, smallest positive normal).
    Log,
    /// √max(a, 0).
    Sqrt,
    /// aⁿ, integer n.
    Powi(i32),
    /// max(a, 0)ᵛ.
    Powf(f64),
    /// min(a, b).
    Min,
    /// max(a, b).
    Max,
}

impl Op {
    /// The value of a one-operand operation (constant folding).
    pub fn apply1(self, a: f64) -> f64 {
        let mut s = vec![a];
        step(self, &mut s, [0.0; 3]);
        s[0]
    }

    /// The value of a two-operand operation (constant folding).
    pub fn apply2(self, a: f64, b: f64) -> f64 {
        let mut s = vec![a, b];
        step(self, &mut s, [0.0; 3]);
        s[0]
    }
}

/// The arithmetic the stack machine needs of a number kind.
pub trait Num: Copy {
    /// A constant.
    fn constant(c: f64) -> Self;
    /// Sum.
    fn add(self, o: Self) -> Self;
    /// Difference.
    fn sub(self, o: Self) -> Self;
    /// Product.
    fn mul(self, o: Self) -> Self;
    /// Quotient.
    fn div(self, o: Self) -> Self;
    /// Negation.
    fn neg(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// The derivative of `abs`: the sign (any value in [−1, 1] at 0).
    fn signum(self) -> Self;
    /// Sine.
    fn sin(self) -> Self;
    /// Cosine.
    fn cos(self) -> Self;
    /// Exponential.
    fn exp(self) -> Self;
    /// Total logarithm.
    fn log(self) -> Self;
    /// Its derivative: 1/a above the smallest positive normal, else 0.
    fn dlog(self) -> Self;
    /// Total square root.
    fn sqrt(self) -> Self;
    /// Its derivative: 1/(2√a) for a > 0, else 0.
    fn dsqrt(self) -> Self;
    /// Integer power.
    fn powi(self, n: i32) -> Self;
    /// Total real power.
    fn powf(self, v: f64) -> Self;
    /// Its derivative: v·a^(v−1) for a > 0, else 0.
    fn dpowf(self, v: f64) -> Self;
    /// Minimum.
    fn min(self, o: Self) -> Self;
    /// Maximum.
    fn max(self, o: Self) -> Self;
    /// The derivative of `min(a, b)`: `da` where a is the smaller, `db` where b is (both where
    /// that is undecided).
    fn pick_min(a: Self, b: Self, da: Self, db: Self) -> Self;
}

impl Num for f64 {
    fn constant(c: f64) -> Self {
        c
    }
    fn add(self, o: Self) -> Self {
        self + o
    }
    fn sub(self, o: Self) -> Self {
        self - o
    }
    fn mul(self, o: Self) -> Self {
        self * o
    }
    fn div(self, o: Self) -> Self {
        self / o
    }
    fn neg(self) -> Self {
        -self
    }
    fn abs(self) -> Self {
        f64::abs(self)
    }
    fn signum(self) -> Self {
        if self > 0.0 {
            1.0
        } else if self < 0.0 {
            -1.0
        } else {
            0.0
        }
    }
    fn sin(self) -> Self {
        f64::sin(self)
    }
    fn cos(self) -> Self {
        f64::cos(self)
    }
    fn exp(self) -> Self {
        f64::exp(self)
    }
    fn log(self) -> Self {
        self.max(f64::MIN_POSITIVE).ln()
    }
    fn dlog(self) -> Self {
        if self > f64::MIN_POSITIVE {
            1.0 / self
        } else {
            0.0
        }
    }
    fn sqrt(self) -> Self {
        self.max(0.0).sqrt()
    }
    fn dsqrt(self) -> Self {
        if self > 0.0 { 0.5 / self.sqrt() } else { 0.0 }
    }
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n)
    }
    fn powf(self, v: f64) -> Self {
        self.max(0.0).powf(v)
    }
    fn dpowf(self, v: f64) -> Self {
        if self > 0.0 {
            v * self.powf(v - 1.0)
        } else {
            0.0
        }
    }
    fn min(self, o: Self) -> Self {
        f64::min(self, o)
    }
    fn max(self, o: Self) -> Self {
        f64::max(self, o)
    }
    fn pick_min(a: Self, b: Self, da: Self, db: Self) -> Self {
        if a <= b { da } else { db }
    }
}

/// A range of values and whether the value may be NaN there (the range then holds every
/// non-NaN value; an operation that turns NaN into a number widens the range to that number).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Iv(pub Interval, pub bool);

const ENTIRE_NAN: Iv = Iv(
    Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    },
    true,
);

/// `[lo, hi]`, may be NaN when `nan`; a NaN bound means a NaN may arise: the whole line.
fn iv(lo: f64, hi: f64, nan: bool) -> Iv {
    if lo.is_nan() || hi.is_nan() {
        ENTIRE_NAN
    } else {
        Iv(Interval { lo, hi }, nan)
    }
}

impl Iv {
    fn contains_zero(self) -> bool {
        self.0.lo <= 0.0 && self.0.hi >= 0.0
    }
    fn finite(self) -> bool {
        self.0.lo.is_finite() && self.0.hi.is_finite()
    }
    /// 1/a for an interval that does not contain 0 (the whole line otherwise).
    fn recip(self) -> Iv {
        if self.contains_zero() {
            ENTIRE_NAN
        } else {
            iv(1.0 / self.0.hi, 1.0 / self.0.lo, self.1)
        }
    }
    /// A sine or cosine range over `self`, widened by the rounding of the argument (`cos` is
    /// taken as a shifted `sin`, whose argument rounds differently from the point `cos`).
    fn trig(self, r: Interval) -> Iv {
        let pad = 2f64.powi(-50) * self.0.lo.abs().max(self.0.hi.abs()).max(1.0);
        iv((r.lo - pad).max(-1.0), (r.hi + pad).min(1.0), self.1)
    }
    /// The smallest range containing both.
    fn hull(self, o: Iv) -> Iv {
        iv(self.0.lo.min(o.0.lo), self.0.hi.max(o.0.hi), self.1 || o.1)
    }
    /// The range of an operation that maps NaN to `v`: widened to `v` where NaN may come in.
    fn or_value(self, nan_in: bool, v: f64) -> Iv {
        let r = Iv(self.0, false);
        if nan_in { r.hull(iv(v, v, false)) } else { r }
    }
}

impl Num for Iv {
    fn constant(c: f64) -> Self {
        iv(c, c, false)
    }
    fn add(self, o: Self) -> Self {
        iv(self.0.lo + o.0.lo, self.0.hi + o.0.hi, self.1 || o.1)
    }
    fn sub(self, o: Self) -> Self {
        iv(self.0.lo - o.0.hi, self.0.hi - o.0.lo, self.1 || o.1)
    }
    fn mul(self, o: Self) -> Self {
        let (a, b) = (self.0, o.0);
        let p = [a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi];
        if p.iter().any(|v| v.is_nan()) {
            return ENTIRE_NAN;
        }
        iv(
            p.iter().copied().fold(f64::INFINITY, f64::min),
            p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            self.1 || o.1,
        )
    }
    fn div(self, o: Self) -> Self {
        if o.contains_zero() {
            return ENTIRE_NAN;
        }
        self.mul(o.recip())
    }
    fn neg(self) -> Self {
        iv(-self.0.hi, -self.0.lo, self.1)
    }
    fn abs(self) -> Self {
        Iv(self.0.abs(), self.1)
    }
    fn signum(self) -> Self {
        iv(
            if self.0.lo > 0.0 { 1.0 } else { -1.0 },
            if self.0.hi < 0.0 { -1.0 } else { 1.0 },
            self.1,
        )
    }
    fn sin(self) -> Self {
        if self.finite() {
            self.trig(sin_interval(self.0))
        } else {
            ENTIRE_NAN
        }
    }
    fn cos(self) -> Self {
        if self.finite() {
            self.trig(cos_interval(self.0))
        } else {
            ENTIRE_NAN
        }
    }
    fn exp(self) -> Self {
        iv(self.0.lo.exp(), self.0.hi.exp(), self.1)
    }
    fn log(self) -> Self {
        iv(Num::log(self.0.lo), Num::log(self.0.hi), false).or_value(self.1, Num::log(f64::NAN))
    }
    fn dlog(self) -> Self {
        let r = if self.0.lo > f64::MIN_POSITIVE {
            iv(1.0 / self.0.hi, 1.0 / self.0.lo, false)
        } else if self.0.hi <= f64::MIN_POSITIVE {
            iv(0.0, 0.0, false)
        } else {
            iv(0.0, f64::INFINITY, false)
        };
        r.or_value(self.1, 0.0)
    }
    fn sqrt(self) -> Self {
        iv(Num::sqrt(self.0.lo), Num::sqrt(self.0.hi), false).or_value(self.1, 0.0)
    }
    fn dsqrt(self) -> Self {
        let r = if self.0.lo > 0.0 {
            iv(0.5 / self.0.hi.sqrt(), 0.5 / self.0.lo.sqrt(), false)
        } else if self.0.hi <= 0.0 {
            iv(0.0, 0.0, false)
        } else {
            iv(0.0, f64::INFINITY, false)
        };
        r.or_value(self.1, 0.0)
    }
    fn powi(self, n: i32) -> Self {
        let (lo, hi) = (self.0.lo, self.0.hi);
        if n == 0 {
            return iv(1.0, 1.0, false);
        }
        if n < 0 {
            return self.powi(-n).recip();
        }
        if n % 2 == 1 {
            return iv(lo.powi(n), hi.powi(n), self.1);
        }
        let a = self.abs().0;
        iv(a.lo.powi(n), a.hi.powi(n), self.1)
    }
    fn powf(self, v: f64) -> Self {
        let (a, b) = (Num::powf(self.0.lo, v), Num::powf(self.0.hi, v));
        iv(a.min(b), a.max(b), false).or_value(self.1, Num::powf(f64::NAN, v))
    }
    fn dpowf(self, v: f64) -> Self {
        let base = iv(self.0.lo.max(0.0), self.0.hi.max(0.0), false);
        let slope = base.powf(v - 1.0).mul(Iv::constant(v));
        let r = if self.0.lo > 0.0 {
            slope
        } else {
            slope.hull(Iv::constant(0.0))
        };
        r.or_value(self.1, 0.0)
    }
    fn min(self, o: Self) -> Self {
        // `f64::min` returns the other operand where one is NaN.
        let mut r = iv(self.0.lo.min(o.0.lo), self.0.hi.min(o.0.hi), false);
        if self.1 {
            r = r.hull(Iv(o.0, false));
        }
        if o.1 {
            r = r.hull(Iv(self.0, false));
        }
        Iv(r.0, self.1 && o.1)
    }
    fn max(self, o: Self) -> Self {
        let mut r = iv(self.0.lo.max(o.0.lo), self.0.hi.max(o.0.hi), false);
        if self.1 {
            r = r.hull(Iv(o.0, false));
        }
        if o.1 {
            r = r.hull(Iv(self.0, false));
        }
        Iv(r.0, self.1 && o.1)
    }
    fn pick_min(a: Self, b: Self, da: Self, db: Self) -> Self {
        if a.1 || b.1 {
            da.hull(db)
        } else if a.0.hi < b.0.lo {
            da
        } else if b.0.hi < a.0.lo {
            db
        } else {
            da.hull(db)
        }
    }
}

/// A value with its gradient (forward-mode differentiation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dual<T> {
    /// The value.
    pub v: T,
    /// ∂/∂x, ∂/∂y, ∂/∂z.
    pub d: [T; 3],
}

impl<T: Num> Dual<T> {
    fn chain(self, v: T, k: T) -> Self {
        Dual {
            v,
            d: self.d.map(|d| d.mul(k)),
        }
    }
}

impl<T: Num> Num for Dual<T> {
    fn constant(c: f64) -> Self {
        Dual {
            v: T::constant(c),
            d: [T::constant(0.0); 3],
        }
    }
    fn add(self, o: Self) -> Self {
        Dual {
            v: self.v.add(o.v),
            d: [0, 1, 2].map(|i| self.d[i].add(o.d[i])),
        }
    }
    fn sub(self, o: Self) -> Self {
        Dual {
            v: self.v.sub(o.v),
            d: [0, 1, 2].map(|i| self.d[i].sub(o.d[i])),
        }
    }
    fn mul(self, o: Self) -> Self {
        Dual {
            v: self.v.mul(o.v),
            d: [0, 1, 2].map(|i| self.d[i].mul(o.v).add(self.v.mul(o.d[i]))),
        }
    }
    fn div(self, o: Self) -> Self {
        let q = self.v.div(o.v);
        Dual {
            v: q,
            d: [0, 1, 2].map(|i| self.d[i].sub(q.mul(o.d[i])).div(o.v)),
        }
    }
    fn neg(self) -> Self {
        self.chain(self.v.neg(), T::constant(-1.0))
    }
    fn abs(self) -> Self {
        self.chain(self.v.abs(), self.v.signum())
    }
    fn signum(self) -> Self {
        Dual {
            v: self.v.signum(),
            d: [T::constant(0.0); 3],
        }
    }
    fn sin(self) -> Self {
        self.chain(self.v.sin(), self.v.cos())
    }
    fn cos(self) -> Self {
        self.chain(self.v.cos(), self.v.sin().neg())
    }
    fn exp(self) -> Self {
        let e = self.v.exp();
        self.chain(e, e)
    }
    fn log(self) -> Self {
        self.chain(self.v.log(), self.v.dlog())
    }
    fn dlog(self) -> Self {
        Dual {
            v: self.v.dlog(),
            d: [T::constant(0.0); 3],
        }
    }
    fn sqrt(self) -> Self {
        self.chain(self.v.sqrt(), self.v.dsqrt())
    }
    fn dsqrt(self) -> Self {
        Dual {
            v: self.v.dsqrt(),
            d: [T::constant(0.0); 3],
        }
    }
    fn powi(self, n: i32) -> Self {
        let k = if n == 0 {
            T::constant(0.0)
        } else {
            self.v.powi(n - 1).mul(T::constant(n as f64))
        };
        self.chain(self.v.powi(n), k)
    }
    fn powf(self, v: f64) -> Self {
        self.chain(self.v.powf(v), self.v.dpowf(v))
    }
    fn dpowf(self, v: f64) -> Self {
        Dual {
            v: self.v.dpowf(v),
            d: [T::constant(0.0); 3],
        }
    }
    fn min(self, o: Self) -> Self {
        Dual {
            v: self.v.min(o.v),
            d: [0, 1, 2].map(|i| T::pick_min(self.v, o.v, self.d[i], o.d[i])),
        }
    }
    fn max(self, o: Self) -> Self {
        Dual {
            v: self.v.max(o.v),
            d: [0, 1, 2].map(|i| T::pick_min(self.v.neg(), o.v.neg(), self.d[i], o.d[i])),
        }
    }
    fn pick_min(a: Self, b: Self, da: Self, db: Self) -> Self {
        Dual {
            v: T::pick_min(a.v, b.v, da.v, db.v),
            d: [0, 1, 2].map(|i| T::pick_min(a.v, b.v, da.d[i], db.d[i])),
        }
    }
}

/// Applies one instruction to the stack; `xyz` are the variables' values.
fn step<T: Num>(op: Op, s: &mut Vec<T>, xyz: [T; 3]) {
    const HAS: &str = "parsed code has its operands";
    macro_rules! unary {
        ($f:expr) => {{
            let a = s.pop().expect(HAS);
            s.push($f(a));
        }};
    }
    macro_rules! binary {
        ($f:expr) => {{
            let b = s.pop().expect(HAS);
            let a = s.pop().expect(HAS);
            s.push($f(a, b));
        }};
    }
    match op {
        Op::X => s.push(xyz[0]),
        Op::Y => s.push(xyz[1]),
        Op::Z => s.push(xyz[2]),
        Op::Const(c) => s.push(T::constant(c)),
        Op::Add => binary!(T::add),
        Op::Sub => binary!(T::sub),
        Op::Mul => binary!(T::mul),
        Op::Div => binary!(T::div),
        Op::Min => binary!(T::min),
        Op::Max => binary!(T::max),
        // Never left in parsed code (the parser turns it into `Powi` or `Powf`).
        Op::Pow => binary!(|a, _| a),
        Op::Neg => unary!(T::neg),
        Op::Abs => unary!(T::abs),
        Op::Sin => unary!(T::sin),
        Op::Cos => unary!(T::cos),
        Op::Exp => unary!(T::exp),
        Op::Log => unary!(T::log),
        Op::Sqrt => unary!(T::sqrt),
        Op::Powi(n) => unary!(|a: T| a.powi(n)),
        Op::Powf(v) => unary!(|a: T| a.powf(v)),
    }
}

/// Runs `code` with the variables at `xyz`, using `stack` as scratch.
pub fn run<T: Num>(code: &[Op], xyz: [T; 3], stack: &mut Vec<T>) -> T {
    stack.clear();
    for &op in code {
        step(op, stack, xyz);
    }
    stack.pop().expect("parsed code leaves one value")
}
