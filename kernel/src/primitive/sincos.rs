//! Double-precision sine and cosine of one argument together, for the hot field paths (the
//! gyroid's values and gradients, evaluated three times per dual-contouring crossing).
//!
//! The C library's `sincos` is accurate but saves and restores the floating-point rounding mode
//! on every call, which cost as much as the evaluation around it. Here: one range reduction by
//! π/2 (Cody–Waite, three parts: the first two have 33 significant bits, so `k` times each is
//! exact for the quotients `k` below 2²⁰ that the accepted arguments give), then the Taylor
//! series of both on the remainder `r`, `|r| ≤ π/4` (to `r¹⁷` and `r¹⁸`: the next terms are below
//! 10⁻¹⁹), and the quadrant picks and signs them. Within a few units in the last place of the
//! library's values for `|x| ≤ 10⁵`; larger or non-finite arguments take the library's path.

use std::f64::consts::FRAC_2_PI;

/// π/2 to 33 significant bits.
const PIO2_1: f64 = 1.570_796_326_734_125_6;
/// The next 33 bits of π/2.
const PIO2_2: f64 = 6.077_100_506_303_966e-11;
/// The rest of π/2, rounded.
const PIO2_3: f64 = 2.022_266_248_795_950_6e-21;
/// Arguments up to this size are reduced here (`k` below 2¹⁷).
const LIMIT: f64 = 1e5;

/// `(sin x, cos x)`.
#[inline]
pub fn sincos_f64(x: f64) -> (f64, f64) {
    if !x.is_finite() || x.abs() > LIMIT {
        return x.sin_cos();
    }
    // Adding 1.5 · 2⁵² rounds to an integer held in the low bits of the sum.
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    let j = x * FRAC_2_PI + MAGIC;
    let k = j - MAGIC;
    let q = j.to_bits();
    let r = ((x - k * PIO2_1) - k * PIO2_2) - k * PIO2_3;
    let r2 = r * r;
    // Taylor coefficients 1/n! with alternating signs, highest power first, in r².
    let s = horner(
        r2,
        &[
            2.811_457_254_345_520_6e-15,
            -7.647_163_731_819_816e-13,
            1.605_904_383_682_161_3e-10,
            -2.505_210_838_544_172e-8,
            2.755_731_922_398_589_3e-6,
            -1.984_126_984_126_984e-4,
            8.333_333_333_333_333e-3,
            -1.666_666_666_666_666_6e-1,
        ],
    );
    // A zero remainder is returned as it is, keeping the sign of −0 as the library does.
    let sin = if r == 0.0 { r } else { r + r * r2 * s };
    let c = horner(
        r2,
        &[
            -1.561_920_696_858_622_5e-16,
            4.779_477_332_387_385e-14,
            -1.147_074_559_772_972_5e-11,
            2.087_675_698_786_81e-9,
            -2.755_731_922_398_589e-7,
            2.480_158_730_158_73e-5,
            -1.388_888_888_888_889e-3,
            4.166_666_666_666_666_4e-2,
        ],
    );
    let half = 0.5 * r2;
    // 1 − r²/2 + r⁴·c, with the large step last and exact where it can be.
    let cos = 1.0 - (half - r2 * r2 * c);
    // Quadrant q: sin x = (s, c, −s, −c)[q], cos x = (c, −s, −c, s)[q].
    let (sin, cos) = if q & 1 == 0 { (sin, cos) } else { (cos, sin) };
    let sin = if q & 2 == 0 { sin } else { -sin };
    let cos = if (q.wrapping_add(1)) & 2 == 0 {
        cos
    } else {
        -cos
    };
    (sin, cos)
}

/// The polynomial with coefficients `c` (highest power first) at `x`, by Horner's rule.
#[inline(always)]
fn horner(x: f64, c: &[f64]) -> f64 {
    c.iter().fold(0.0, |acc, &k| acc * x + k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitive::conformance::Rng;

    /// Both within `tol` of the library's values.
    fn close(x: f64, tol: f64) {
        let (s, c) = sincos_f64(x);
        let (ls, lc) = x.sin_cos();
        assert!((s - ls).abs() <= tol, "sin {x}: {s} vs {ls}");
        assert!((c - lc).abs() <= tol, "cos {x}: {c} vs {lc}");
        assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x}: {s} {c}");
    }

    #[test]
    fn agrees_with_the_library_to_a_few_ulps() {
        // Values lie in [−1, 1]: a few ulps of 1 is 4.5e-16.
        let mut rng = Rng::new(11);
        for i in -100_000..100_000 {
            close(i as f64 * 1e-3, 4.5e-16);
            close(rng.next() * 2e5 - 1e5, 4.5e-16);
            close(rng.next() * 20.0 - 10.0, 4.5e-16);
        }
        // Near the quadrant boundaries and near zero, where the remainder cancels.
        for k in -2000..2000 {
            let b = k as f64 * std::f64::consts::FRAC_PI_2;
            for d in [0.0, 1e-300, 1e-17, 1e-9, -1e-9, 3e-5] {
                close(b + d, 4.5e-16);
            }
        }
    }

    #[test]
    fn small_arguments_are_relatively_accurate() {
        let mut x = 1e-300;
        while x < 1.0 {
            for v in [x, -x] {
                let (s, c) = sincos_f64(v);
                let (ls, lc) = v.sin_cos();
                assert!((s - ls).abs() <= 2.3e-16 * ls.abs(), "sin {v}: {s} vs {ls}");
                assert!((c - lc).abs() <= 2.3e-16, "cos {v}: {c} vs {lc}");
            }
            x *= 1.7;
        }
        assert_eq!(sincos_f64(0.0), (0.0, 1.0));
        assert!(sincos_f64(-0.0).0.is_sign_negative());
    }

    #[test]
    fn large_and_special_arguments_take_the_library_path() {
        for x in [1e5 + 0.5, -3e7, 1e300, f64::MAX] {
            assert_eq!(sincos_f64(x), x.sin_cos());
        }
        assert!(sincos_f64(f64::NAN).0.is_nan());
        assert!(sincos_f64(f64::INFINITY).1.is_nan());
    }
}
