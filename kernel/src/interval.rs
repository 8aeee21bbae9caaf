//! Closed intervals of reals and the arithmetic needed to bound a field over a box.
//!
//! Every operation returns an interval that contains all results of the operation applied to
//! members of its operands (inclusion property); that is what makes octree culling safe.

use std::ops::{Add, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` with `lo <= hi`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

impl Interval {
    /// The interval `[lo, hi]`; the bounds are swapped if given in the wrong order.
    pub fn new(lo: f64, hi: f64) -> Self {
        if lo <= hi {
            Self { lo, hi }
        } else {
            Self { lo: hi, hi: lo }
        }
    }

    /// The degenerate interval `[x, x]`.
    pub fn point(x: f64) -> Self {
        Self { lo: x, hi: x }
    }

    /// The whole real line.
    pub fn entire() -> Self {
        Self {
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
        }
    }

    /// `value ± radius`, the Lipschitz bound of a field with value `value` at a box centre.
    pub fn around(value: f64, radius: f64) -> Self {
        Self {
            lo: value - radius,
            hi: value + radius,
        }
    }

    /// True when `x` lies in the interval.
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// Width `hi - lo`.
    pub fn width(&self) -> f64 {
        self.hi - self.lo
    }

    /// Interval of `x²`.
    pub fn sqr(self) -> Self {
        if self.lo >= 0.0 {
            Self {
                lo: self.lo * self.lo,
                hi: self.hi * self.hi,
            }
        } else if self.hi <= 0.0 {
            Self {
                lo: self.hi * self.hi,
                hi: self.lo * self.lo,
            }
        } else {
            Self {
                lo: 0.0,
                hi: (self.lo * self.lo).max(self.hi * self.hi),
            }
        }
    }

    /// Interval of `√x`, with negative parts clamped to zero.
    pub fn sqrt(self) -> Self {
        Self {
            lo: self.lo.max(0.0).sqrt(),
            hi: self.hi.max(0.0).sqrt(),
        }
    }

    /// Interval of `|x|`.
    pub fn abs(self) -> Self {
        if self.lo >= 0.0 {
            self
        } else if self.hi <= 0.0 {
            -self
        } else {
            Self {
                lo: 0.0,
                hi: (-self.lo).max(self.hi),
            }
        }
    }

    /// Interval of `min(x, y)`.
    pub fn min(self, other: Self) -> Self {
        Self {
            lo: self.lo.min(other.lo),
            hi: self.hi.min(other.hi),
        }
    }

    /// Interval of `max(x, y)`.
    pub fn max(self, other: Self) -> Self {
        Self {
            lo: self.lo.max(other.lo),
            hi: self.hi.max(other.hi),
        }
    }

    /// Interval of `x · k` for a scalar `k`.
    pub fn scale(self, k: f64) -> Self {
        Self::new(self.lo * k, self.hi * k)
    }

    /// Interval of the Euclidean norm of a vector whose components lie in `c`.
    pub fn norm(c: &[Interval]) -> Self {
        c.iter()
            .fold(Interval::point(0.0), |acc, x| acc + x.sqr())
            .sqrt()
    }
}

impl Add for Interval {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self {
            lo: self.lo + o.lo,
            hi: self.hi + o.hi,
        }
    }
}

impl Sub for Interval {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self {
            lo: self.lo - o.hi,
            hi: self.hi - o.lo,
        }
    }
}

impl Neg for Interval {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        Self {
            lo: p.iter().copied().fold(f64::INFINITY, f64::min),
            hi: p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Inclusion property checked on a grid of members of each operand.
    #[test]
    fn operations_contain_all_pointwise_results() {
        let ivs = [
            Interval::new(-2.0, -0.5),
            Interval::new(-1.0, 3.0),
            Interval::new(0.25, 2.0),
            Interval::point(-1.5),
        ];
        let members = |i: Interval| (0..=8).map(move |k| i.lo + i.width() * k as f64 / 8.0);
        for &a in &ivs {
            for x in members(a) {
                assert!(a.sqr().contains(x * x));
                assert!(a.abs().contains(x.abs()));
                assert!((-a).contains(-x));
                assert!(a.scale(-3.0).contains(-3.0 * x));
                if x >= 0.0 {
                    assert!(a.sqrt().contains(x.sqrt()));
                }
                for &b in &ivs {
                    for y in members(b) {
                        assert!((a + b).contains(x + y));
                        assert!((a - b).contains(x - y));
                        assert!((a * b).contains(x * y));
                        assert!(a.min(b).contains(x.min(y)));
                        assert!(a.max(b).contains(x.max(y)));
                    }
                }
            }
        }
    }

    #[test]
    fn norm_bounds_vector_length() {
        let c = [
            Interval::new(-1.0, 2.0),
            Interval::new(3.0, 4.0),
            Interval::point(0.0),
        ];
        let n = Interval::norm(&c);
        assert!(n.contains(3.0) && n.contains((4.0f64 + 16.0).sqrt()));
        assert!(n.lo >= 3.0 - 1e-12);
    }
}
