//! Interleaved points (x, y, z per row of an N × 3 array) split into the coordinate arrays the
//! batch evaluator reads, converted to single precision on the way.
//!
//! On x86-64 with AVX2 eight points go at a time through three loads, six blends, three lane
//! permutations and three stores (float64 input: six loads and six conversions first); elsewhere
//! a scalar loop. Both give the same bits: the vector conversion rounds to nearest like `as f32`.

/// A coordinate type an N × 3 array may hold: `f32` as it is, `f64` rounded to nearest.
pub trait Coordinate: Copy + Sync + Send {
    /// Splits `p` (x, y, z of `x.len()` points) into `x`, `y`, `z`.
    fn deinterleave(p: &[Self], x: &mut [f32], y: &mut [f32], z: &mut [f32]);
}

impl Coordinate for f32 {
    fn deinterleave(p: &[f32], x: &mut [f32], y: &mut [f32], z: &mut [f32]) {
        let done = vector::f32s(p, x, y, z);
        scalar(
            &p[3 * done..],
            &mut x[done..],
            &mut y[done..],
            &mut z[done..],
            |v| v,
        );
    }
}

impl Coordinate for f64 {
    fn deinterleave(p: &[f64], x: &mut [f32], y: &mut [f32], z: &mut [f32]) {
        let done = vector::f64s(p, x, y, z);
        scalar(
            &p[3 * done..],
            &mut x[done..],
            &mut y[done..],
            &mut z[done..],
            |v| v as f32,
        );
    }
}

/// The portable loop, one point at a time.
fn scalar<T: Copy>(
    p: &[T],
    x: &mut [f32],
    y: &mut [f32],
    z: &mut [f32],
    to_f32: impl Fn(T) -> f32,
) {
    for (((c, x), y), z) in p.chunks_exact(3).zip(x).zip(y).zip(z) {
        *x = to_f32(c[0]);
        *y = to_f32(c[1]);
        *z = to_f32(c[2]);
    }
}

#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
mod vector {
    //! The AVX2 loops; each returns how many points it split (a multiple of eight, 0 without
    //! AVX2), the caller finishes the rest.
    use std::arch::x86_64::{
        __m128, __m256, _mm256_blend_ps, _mm256_castps128_ps256, _mm256_cvtpd_ps,
        _mm256_insertf128_ps, _mm256_loadu_pd, _mm256_loadu_ps, _mm256_permutevar8x32_ps,
        _mm256_setr_epi32, _mm256_storeu_ps,
    };

    /// Eight interleaved points in three registers (`a` = x0 y0 z0 x1 y1 z1 x2 y2, `b` = z2 …
    /// x5, `c` = y5 … z7) as x0…x7, y0…y7, z0…z7.
    #[target_feature(enable = "avx2")]
    #[inline]
    fn split(a: __m256, b: __m256, c: __m256) -> [__m256; 3] {
        // x sits in lanes 0, 3, 6 of a, 1, 4, 7 of b and 2, 5 of c: blended it reads
        // x0 x3 x6 x1 x4 x7 x2 x5, and the permutation puts it in order; y and z likewise.
        let x = _mm256_blend_ps::<0b0010_0100>(_mm256_blend_ps::<0b1001_0010>(a, b), c);
        let y = _mm256_blend_ps::<0b0100_1001>(_mm256_blend_ps::<0b0010_0100>(a, b), c);
        let z = _mm256_blend_ps::<0b1001_0010>(_mm256_blend_ps::<0b0100_1001>(a, b), c);
        [
            _mm256_permutevar8x32_ps(x, _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5)),
            _mm256_permutevar8x32_ps(y, _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6)),
            _mm256_permutevar8x32_ps(z, _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7)),
        ]
    }

    /// Stores the three registers of [`split`] at point `i`.
    #[target_feature(enable = "avx2")]
    #[inline]
    fn store([vx, vy, vz]: [__m256; 3], x: &mut [f32], y: &mut [f32], z: &mut [f32], i: usize) {
        let (x, y, z) = (&mut x[i..i + 8], &mut y[i..i + 8], &mut z[i..i + 8]);
        // SAFETY: each slice holds the eight floats written (bounds checked just above).
        unsafe {
            _mm256_storeu_ps(x.as_mut_ptr(), vx);
            _mm256_storeu_ps(y.as_mut_ptr(), vy);
            _mm256_storeu_ps(z.as_mut_ptr(), vz);
        }
    }

    /// Single-precision points, eight at a time.
    pub fn f32s(p: &[f32], x: &mut [f32], y: &mut [f32], z: &mut [f32]) -> usize {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return 0;
        }
        // SAFETY: AVX2 was detected on this CPU.
        unsafe { f32s_avx2(p, x, y, z) }
    }

    #[target_feature(enable = "avx2")]
    fn f32s_avx2(p: &[f32], x: &mut [f32], y: &mut [f32], z: &mut [f32]) -> usize {
        let n = (p.len() / 3).min(x.len()).min(y.len()).min(z.len()) / 8 * 8;
        for (i, block) in p[..3 * n].chunks_exact(24).enumerate() {
            let q = block.as_ptr();
            // SAFETY: `block` holds 24 floats, read as three unaligned groups of eight.
            let (a, b, c) = unsafe {
                (
                    _mm256_loadu_ps(q),
                    _mm256_loadu_ps(q.add(8)),
                    _mm256_loadu_ps(q.add(16)),
                )
            };
            store(split(a, b, c), x, y, z, 8 * i);
        }
        n
    }

    /// Double-precision points, rounded to single precision, eight at a time.
    pub fn f64s(p: &[f64], x: &mut [f32], y: &mut [f32], z: &mut [f32]) -> usize {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return 0;
        }
        // SAFETY: AVX2 (and so AVX) was detected on this CPU.
        unsafe { f64s_avx2(p, x, y, z) }
    }

    /// Four doubles at `q` and the four after them, rounded, as one register.
    ///
    /// # Safety
    /// `q` points to eight readable doubles.
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn eight(q: *const f64) -> __m256 {
        // SAFETY: the caller passes a pointer to eight readable doubles.
        unsafe {
            let lo: __m128 = _mm256_cvtpd_ps(_mm256_loadu_pd(q));
            let hi: __m128 = _mm256_cvtpd_ps(_mm256_loadu_pd(q.add(4)));
            _mm256_insertf128_ps::<1>(_mm256_castps128_ps256(lo), hi)
        }
    }

    #[target_feature(enable = "avx2")]
    fn f64s_avx2(p: &[f64], x: &mut [f32], y: &mut [f32], z: &mut [f32]) -> usize {
        let n = (p.len() / 3).min(x.len()).min(y.len()).min(z.len()) / 8 * 8;
        for (i, block) in p[..3 * n].chunks_exact(24).enumerate() {
            let q = block.as_ptr();
            // SAFETY: `block` holds 24 doubles, read as three groups of eight.
            let (a, b, c) = unsafe { (eight(q), eight(q.add(8)), eight(q.add(16))) };
            store(split(a, b, c), x, y, z, 8 * i);
        }
        n
    }
}

#[cfg(not(target_arch = "x86_64"))]
mod vector {
    //! No vector loops on this architecture: the scalar loop splits every point.

    /// Splits nothing.
    pub fn f32s(_: &[f32], _: &mut [f32], _: &mut [f32], _: &mut [f32]) -> usize {
        0
    }

    /// Splits nothing.
    pub fn f64s(_: &[f64], _: &mut [f32], _: &mut [f32], _: &mut [f32]) -> usize {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::Coordinate;

    fn check<T: Coordinate + PartialEq + std::fmt::Debug>(p: &[T], to_f32: impl Fn(T) -> f32) {
        let n = p.len() / 3;
        let (mut x, mut y, mut z) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        T::deinterleave(p, &mut x, &mut y, &mut z);
        for i in 0..n {
            assert_eq!(x[i].to_bits(), to_f32(p[3 * i]).to_bits(), "x of point {i}");
            assert_eq!(
                y[i].to_bits(),
                to_f32(p[3 * i + 1]).to_bits(),
                "y of point {i}"
            );
            assert_eq!(
                z[i].to_bits(),
                to_f32(p[3 * i + 2]).to_bits(),
                "z of point {i}"
            );
        }
    }

    /// Every lane of the vector path lands where the scalar loop puts it, for every length
    /// around the eight-point blocks, and double-precision rounding matches `as f32` (ties,
    /// overflow to infinity, subnormals, NaN).
    #[test]
    fn vector_and_scalar_paths_agree() {
        let specials = [
            1.0 + f64::EPSILON,
            1.0 + 2f64.powi(-24),
            1.0 + 3.0 * 2f64.powi(-24),
            -1e300,
            1e-42,
            f64::NAN,
            f64::INFINITY,
            -0.0,
            3.4028235677973366e38,
        ];
        for n in 0..40 {
            let p64: Vec<f64> = (0..3 * n)
                .map(|k| {
                    if k % 5 == 4 {
                        specials[k % specials.len()]
                    } else {
                        k as f64 * 1.000_000_1 - 7.3
                    }
                })
                .collect();
            check(&p64, |v| v as f32);
            let p32: Vec<f32> = p64.iter().map(|&v| v as f32).collect();
            check(&p32, |v| v);
        }
    }
}
