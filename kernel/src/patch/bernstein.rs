//! Bernstein polynomials `B_i^n(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ` and the evaluation of Bézier sums
//! `Σ c_i B_i^n(t)` without a work array (a Horner scheme in `t` and `1 − t`), so height fields
//! and patches of any degree evaluate without allocating.

use std::ops::{Add, Mul};

/// `Σ_{i=0}^{n} c(i) B_i^n(t)` by the Bernstein–Horner scheme
/// `((c₀ s + C(n,1) t c₁) s + C(n,2) t² c₂) s + … + tⁿ cₙ` with `s = 1 − t`. Numerically stable on
/// `[0, 1]` (every step adds non-negative multiples); `c` is called once per index.
#[inline]
pub fn bezier_sum<T>(n: usize, t: f64, c: impl Fn(usize) -> T) -> T
where
    T: Copy + Add<Output = T> + Mul<f64, Output = T>,
{
    if n == 0 {
        return c(0);
    }
    let s = 1.0 - t;
    let mut binom = 1.0;
    let mut tn = 1.0;
    let mut acc = c(0) * s;
    for i in 1..n {
        binom = binom * (n - i + 1) as f64 / i as f64;
        tn *= t;
        acc = (acc + c(i) * (binom * tn)) * s;
    }
    acc + c(n) * (tn * t)
}

/// `B_i^n(t)`.
pub fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    if i > n {
        return 0.0;
    }
    binomial(n, i) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
}

/// The binomial coefficient `C(n, k)` as a float (exact for the degrees used here).
pub fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
}

/// `Σ_i Σ_j c(i, j) B_i^m(u) B_j^n(v)`, the tensor-product sum (rows summed in `u` first).
#[inline]
pub fn tensor_sum<T>(m: usize, n: usize, u: f64, v: f64, c: impl Fn(usize, usize) -> T) -> T
where
    T: Copy + Add<Output = T> + Mul<f64, Output = T>,
{
    bezier_sum(n, v, |j| bezier_sum(m, u, |i| c(i, j)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horner_scheme_matches_the_definition() {
        for n in 0..12 {
            for k in 0..=20 {
                let t = k as f64 / 20.0;
                let c = |i: usize| (i as f64 * 0.7).sin() + 0.1 * i as f64;
                let direct: f64 = (0..=n).map(|i| c(i) * bernstein(n, i, t)).sum();
                let horner = bezier_sum(n, t, c);
                assert!((direct - horner).abs() < 1e-12, "n {n} t {t}");
            }
        }
    }

    #[test]
    fn partition_of_unity_and_endpoints() {
        for n in 1..10 {
            assert!((bezier_sum(n, 0.37, |_| 1.0) - 1.0).abs() < 1e-14);
            assert_eq!(bezier_sum(n, 0.0, |i| i as f64), 0.0);
            assert!((bezier_sum(n, 1.0, |i| i as f64) - n as f64).abs() < 1e-12);
        }
        assert_eq!(binomial(10, 3), 120.0);
    }
}
