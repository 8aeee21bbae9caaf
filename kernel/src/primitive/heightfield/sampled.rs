//! Height from samples on a regular grid over `[0, 1]²`: bilinear interpolation (C⁰, exact range
//! and slopes from the samples), OpenSCAD's four triangles per cell (C⁰, the same bounds) or bicubic Catmull–Rom interpolation (C¹, interpolating, with
//! clamped samples past the border). Bicubic bounds convert each cell to its bicubic Bézier form
//! (per axis: `b₀ = p₁`, `b₁ = p₁ + (p₂ − p₀)/6`, `b₂ = p₂ − (p₃ − p₁)/6`, `b₃ = p₂`) and use the
//! convex-hull property of its (differenced) control net.

use super::grid::HeightGrid;
use super::param::{ParamBounds, ParamDerivatives};

/// The cell containing parameter `u` along an axis of `n` samples, and the local parameter.
#[inline]
fn cell(u: f64, n: usize) -> (usize, f64) {
    let s = u * (n - 1) as f64;
    let i = (s.floor().max(0.0) as usize).min(n - 2);
    (i, s - i as f64)
}

/// The local parameters `(t, s)` of `(u, v)` in its cell and the cell's four corner heights
/// `[z00, z10, z01, z11]` (first index along `u`).
#[inline]
fn corners(g: &HeightGrid, u: f64, v: f64) -> (f64, f64, [f64; 4]) {
    let (i, t) = cell(u, g.nx());
    let (j, s) = cell(v, g.ny());
    let z = [
        g.get(i, j),
        g.get(i + 1, j),
        g.get(i, j + 1),
        g.get(i + 1, j + 1),
    ];
    (t, s, z)
}

/// `h` and its derivatives in `(u, v)` by bilinear interpolation.
#[inline]
pub(super) fn bilinear(g: &HeightGrid, u: f64, v: f64) -> ParamDerivatives {
    let (t, s, [z00, z10, z01, z11]) = corners(g, u, v);
    let (ku, kv) = ((g.nx() - 1) as f64, (g.ny() - 1) as f64);
    let bottom = z00 + t * (z10 - z00);
    let top = z01 + t * (z11 - z01);
    ParamDerivatives {
        h: bottom + s * (top - bottom),
        hu: ku * ((1.0 - s) * (z10 - z00) + s * (z11 - z01)),
        hv: kv * (top - bottom),
        huu: 0.0,
        huv: ku * kv * (z11 - z10 - z01 + z00),
        hvv: 0.0,
    }
}

/// `h` and its derivatives in `(u, v)` over OpenSCAD's `surface()` triangles: the cell's centre
/// at the mean `c` of its four corners, and the cell split by its diagonals into four flat
/// triangles, each through two corners and the centre. Across a triangle's inner edges the slope
/// jumps; the height is continuous. Each slope is a sample step or the mean of two opposite ones,
/// so [`bilinear_bounds`] bound it too.
#[inline]
pub(super) fn quads(g: &HeightGrid, u: f64, v: f64) -> ParamDerivatives {
    let (t, s, [z00, z10, z01, z11]) = corners(g, u, v);
    let c2 = 0.5 * (z00 + z10 + z01 + z11);
    let (dx, dy) = (t - 0.5, s - 0.5);
    // (h, ∂h/∂t, ∂h/∂s) on the triangle containing (t, s).
    let (h, ht, hs) = if dy.abs() >= dx.abs() {
        if dy <= 0.0 {
            let m = c2 - z00 - z10;
            (z00 + t * (z10 - z00) + s * m, z10 - z00, m)
        } else {
            let m = c2 - z01 - z11;
            (z01 + t * (z11 - z01) + (1.0 - s) * m, z11 - z01, -m)
        }
    } else if dx <= 0.0 {
        let m = c2 - z00 - z01;
        (z00 + s * (z01 - z00) + t * m, m, z01 - z00)
    } else {
        let m = c2 - z10 - z11;
        (z10 + s * (z11 - z10) + (1.0 - t) * m, -m, z11 - z10)
    };
    let (ku, kv) = ((g.nx() - 1) as f64, (g.ny() - 1) as f64);
    ParamDerivatives {
        h,
        hu: ku * ht,
        hv: kv * hs,
        huu: 0.0,
        huv: 0.0,
        hvv: 0.0,
    }
}

/// Catmull–Rom weights of the four samples around a cell, and their first and second derivatives.
#[inline]
fn weights(t: f64) -> [[f64; 4]; 3] {
    let (t2, t3) = (t * t, t * t * t);
    [
        [
            0.5 * (-t + 2.0 * t2 - t3),
            0.5 * (2.0 - 5.0 * t2 + 3.0 * t3),
            0.5 * (t + 4.0 * t2 - 3.0 * t3),
            0.5 * (-t2 + t3),
        ],
        [
            0.5 * (-1.0 + 4.0 * t - 3.0 * t2),
            0.5 * (-10.0 * t + 9.0 * t2),
            0.5 * (1.0 + 8.0 * t - 9.0 * t2),
            0.5 * (-2.0 * t + 3.0 * t2),
        ],
        [
            0.5 * (4.0 - 6.0 * t),
            0.5 * (-10.0 + 18.0 * t),
            0.5 * (8.0 - 18.0 * t),
            0.5 * (-2.0 + 6.0 * t),
        ],
    ]
}

/// `h` and its derivatives in `(u, v)` by bicubic Catmull–Rom interpolation.
#[inline]
pub(super) fn bicubic(g: &HeightGrid, u: f64, v: f64) -> ParamDerivatives {
    let (i, t) = cell(u, g.nx());
    let (j, s) = cell(v, g.ny());
    let (wu, wv) = (weights(t), weights(s));
    // sums[a][b] = Σ wu[a][k] wv[b][l] z(i − 1 + k, j − 1 + l)
    let mut sums = [[0.0; 3]; 3];
    for l in 0..4usize {
        let mut row = [0.0; 3];
        for k in 0..4usize {
            let z = g.get_clamped(i as isize - 1 + k as isize, j as isize - 1 + l as isize);
            for (r, w) in row.iter_mut().zip(&wu) {
                *r += w[k] * z;
            }
        }
        for (sum, r) in sums.iter_mut().zip(row) {
            for (s, w) in sum.iter_mut().zip(&wv) {
                *s += w[l] * r;
            }
        }
    }
    let (ku, kv) = ((g.nx() - 1) as f64, (g.ny() - 1) as f64);
    ParamDerivatives {
        h: sums[0][0],
        hu: ku * sums[1][0],
        hv: kv * sums[0][1],
        huu: ku * ku * sums[2][0],
        huv: ku * kv * sums[1][1],
        hvv: kv * kv * sums[0][2],
    }
}

/// Bounds of bilinear interpolation: samples' range and steepest steps; no second-derivative bound
/// (the slope jumps across cells).
pub(super) fn bilinear_bounds(g: &HeightGrid) -> ParamBounds {
    let (lo, hi) = g.range();
    let (su, sv) = g.max_steps();
    ParamBounds {
        lo,
        hi,
        hu: (g.nx() - 1) as f64 * su,
        hv: (g.ny() - 1) as f64 * sv,
        second: None,
    }
}

/// Bounds of bicubic interpolation from each cell's Bézier control net (see the module docs).
pub(super) fn bicubic_bounds(g: &HeightGrid) -> ParamBounds {
    // Rows of the Catmull–Rom → Bézier conversion: b = C p.
    const C: [[f64; 4]; 4] = [
        [0.0, 1.0, 0.0, 0.0],
        [-1.0 / 6.0, 1.0, 1.0 / 6.0, 0.0],
        [0.0, 1.0 / 6.0, 1.0, -1.0 / 6.0],
        [0.0, 0.0, 1.0, 0.0],
    ];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let (mut su, mut sv, mut suu, mut suv, mut svv) = (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for j in 0..g.ny() - 1 {
        for i in 0..g.nx() - 1 {
            let mut p = [[0.0; 4]; 4];
            for (k, col) in p.iter_mut().enumerate() {
                for (l, z) in col.iter_mut().enumerate() {
                    *z = g.get_clamped(i as isize - 1 + k as isize, j as isize - 1 + l as isize);
                }
            }
            // b = C p Cᵀ (k along u, l along v).
            let mut cp = [[0.0; 4]; 4];
            for a in 0..4 {
                for l in 0..4 {
                    cp[a][l] = (0..4).map(|k| C[a][k] * p[k][l]).sum();
                }
            }
            let mut b = [[0.0; 4]; 4];
            for a in 0..4 {
                for c in 0..4 {
                    b[a][c] = (0..4).map(|l| cp[a][l] * C[c][l]).sum();
                }
            }
            for a in 0..4 {
                for c in 0..4 {
                    lo = lo.min(b[a][c]);
                    hi = hi.max(b[a][c]);
                    if a < 3 {
                        su = su.max((b[a + 1][c] - b[a][c]).abs());
                    }
                    if c < 3 {
                        sv = sv.max((b[a][c + 1] - b[a][c]).abs());
                    }
                    if a < 2 {
                        suu = suu.max((b[a + 2][c] - 2.0 * b[a + 1][c] + b[a][c]).abs());
                    }
                    if c < 2 {
                        svv = svv.max((b[a][c + 2] - 2.0 * b[a][c + 1] + b[a][c]).abs());
                    }
                    if a < 3 && c < 3 {
                        let t = b[a + 1][c + 1] - b[a + 1][c] - b[a][c + 1] + b[a][c];
                        suv = suv.max(t.abs());
                    }
                }
            }
        }
    }
    let (ku, kv) = ((g.nx() - 1) as f64, (g.ny() - 1) as f64);
    ParamBounds {
        lo,
        hi,
        hu: 3.0 * ku * su,
        hv: 3.0 * kv * sv,
        second: Some((
            6.0 * ku * ku * suu,
            9.0 * ku * kv * suv,
            6.0 * kv * kv * svv,
        )),
    }
}
