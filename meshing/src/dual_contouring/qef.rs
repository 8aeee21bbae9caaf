//! The quadratic error function of dual contouring: `E(x) = Σ (nᵢ · (x − pᵢ))²` over surface
//! points `pᵢ` with unit normals `nᵢ`, stored as `AᵀA`, `Aᵀb`, `bᵀb` relative to a reference point
//! (so sums stay well conditioned), plus the mass point of the `pᵢ`.
//!
//! Minimised with a symmetric eigen-decomposition (cyclic Jacobi) of `AᵀA`: eigenvalues below
//! [`EIGEN_CUTOFF`] times the largest are dropped, so along flat or nearly flat directions the
//! solution stays at the mass point (rank-revealing pseudo-inverse, the mass point as fallback).

use glam::{DMat3, DVec3};

/// Relative eigenvalue cutoff of the pseudo-inverse.
pub(crate) const EIGEN_CUTOFF: f64 = 0.02;

/// A QEF about `reference`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Qef {
    /// Point the sums are relative to.
    pub reference: DVec3,
    /// `AᵀA` as `xx, xy, xz, yy, yz, zz`.
    pub ata: [f64; 6],
    /// `Aᵀb`.
    pub atb: DVec3,
    /// `bᵀb`.
    pub btb: f64,
    /// Sum of the points, relative to the reference.
    pub mass: DVec3,
    /// Number of points.
    pub count: u32,
}

impl Qef {
    /// An empty QEF about `reference`.
    pub fn new(reference: DVec3) -> Self {
        Self {
            reference,
            ata: [0.0; 6],
            atb: DVec3::ZERO,
            btb: 0.0,
            mass: DVec3::ZERO,
            count: 0,
        }
    }

    /// Adds the plane through `p` with unit normal `n`.
    pub fn add(&mut self, p: DVec3, n: DVec3) {
        let q = p - self.reference;
        let d = n.dot(q);
        let a = &mut self.ata;
        a[0] += n.x * n.x;
        a[1] += n.x * n.y;
        a[2] += n.x * n.z;
        a[3] += n.y * n.y;
        a[4] += n.y * n.z;
        a[5] += n.z * n.z;
        self.atb += n * d;
        self.btb += d * d;
        self.mass += q;
        self.count += 1;
    }

    fn matrix(&self) -> DMat3 {
        let a = &self.ata;
        DMat3::from_cols(
            DVec3::new(a[0], a[1], a[2]),
            DVec3::new(a[1], a[3], a[4]),
            DVec3::new(a[2], a[4], a[5]),
        )
    }

    /// The same QEF about another reference point.
    pub fn shifted(&self, reference: DVec3) -> Self {
        let s = self.reference - reference; // q' = q + s
        let m = self.matrix();
        let ms = m * s;
        Self {
            reference,
            ata: self.ata,
            atb: self.atb + ms,
            btb: self.btb + 2.0 * s.dot(self.atb) + s.dot(ms),
            mass: self.mass + s * self.count as f64,
            count: self.count,
        }
    }

    /// Adds another QEF (moved to this one's reference).
    pub fn merge(&mut self, other: &Qef) {
        let o = other.shifted(self.reference);
        for (a, b) in self.ata.iter_mut().zip(o.ata) {
            *a += b;
        }
        self.atb += o.atb;
        self.btb += o.btb;
        self.mass += o.mass;
        self.count += o.count;
    }

    /// `E(x)` at world point `x`.
    pub fn error(&self, x: DVec3) -> f64 {
        let q = x - self.reference;
        (q.dot(self.matrix() * q) - 2.0 * q.dot(self.atb) + self.btb).max(0.0)
    }

    /// The minimiser (pseudo-inverse about the mass point), clamped into `[lo, hi]`, and its error.
    pub fn solve(&self, lo: DVec3, hi: DVec3) -> (DVec3, f64) {
        let c = self.mass / self.count.max(1) as f64;
        let m = self.matrix();
        let rhs = self.atb - m * c;
        let x = c + match dominant(m) {
            Some((value, v)) => v * (v.dot(rhs) / value),
            None => pseudo_inverse_times(m, rhs),
        };
        let mut p = self.reference + x;
        if !p.is_finite() {
            p = self.reference + c;
        }
        let p = p.clamp(lo, hi);
        (p, self.error(p))
    }
}

/// `m⁺ rhs` for the positive semi-definite `m`, with the pseudo-inverse that drops eigenvalues
/// below [`EIGEN_CUTOFF`] times the largest.
///
/// From the closed-form eigenvalues: with all three kept, `m⁻¹ rhs`; with two, the third
/// eigenvector `w` (a null vector of `m − λ₃I`) is removed from `rhs` and the system solved with
/// `m + λ₁wwᵀ` (the same on the kept directions, and well conditioned); with one, its eigenvector
/// (a null vector of `m − λ₁I`). Where an eigenvalue the answer depends on is too close to
/// another for its null vector to be accurate, the Jacobi decomposition decides instead.
fn pseudo_inverse_times(m: DMat3, rhs: DVec3) -> DVec3 {
    let [low, mid, top] = symmetric_eigenvalues(m);
    if !(top > 0.0 && top.is_finite()) {
        return DVec3::ZERO;
    }
    let cut = EIGEN_CUTOFF * top;
    let kept = [low, mid].iter().filter(|&&l| l.abs() > cut).count() + 1;
    // Keep clear of the cutoff itself, where the rank (and the answer) jumps.
    let near_cut = [low, mid]
        .iter()
        .any(|&l| (l.abs() - cut).abs() <= 1e-9 * top);
    let solved = if near_cut {
        None
    } else {
        match kept {
            3 => Some(m.inverse() * rhs),
            2 => null_vector(m, low, mid - low, top).map(|w| {
                let shifted = m + DMat3::from_cols(w * w.x, w * w.y, w * w.z) * top;
                shifted.inverse() * (rhs - w * w.dot(rhs))
            }),
            _ => null_vector(m, top, top - mid, top).map(|v| v * (v.dot(rhs) / top)),
        }
    };
    match solved {
        Some(x) if x.is_finite() => x,
        _ => pseudo_inverse_jacobi(m, rhs),
    }
}

/// The unit null vector of `m − λI` (an eigenvector of `m` for `λ`), when the nearest other
/// eigenvalue is at least `gap` away (relative to the scale `top`) so that it is well defined:
/// the longest cross product of two rows. `None` when the gap is too small to trust it.
fn null_vector(m: DMat3, lambda: f64, gap: f64, top: f64) -> Option<DVec3> {
    if gap <= 1e-6 * top {
        return None;
    }
    let b = m - DMat3::from_diagonal(DVec3::splat(lambda));
    let (r0, r1, r2) = (b.row(0), b.row(1), b.row(2));
    let candidates = [r0.cross(r1), r0.cross(r2), r1.cross(r2)];
    let best = candidates
        .into_iter()
        .max_by(|a, b| a.length_squared().total_cmp(&b.length_squared()))
        .expect("three candidates");
    // The cross products of `m − λI` have length up to the product of the other two
    // eigenvalues' distances from `λ`; far below that, rounding dominates.
    let len = best.length();
    (len > 1e-3 * gap * top).then(|| best / len)
}

/// Eigenvalues of a symmetric 3 × 3 matrix in ascending order (trigonometric closed form).
fn symmetric_eigenvalues(m: DMat3) -> [f64; 3] {
    let (a, b, c) = (m.x_axis.x, m.y_axis.y, m.z_axis.z);
    let (d, e, f) = (m.y_axis.x, m.z_axis.y, m.z_axis.x);
    let p1 = d * d + e * e + f * f;
    let q = (a + b + c) / 3.0;
    let p2 = (a - q).powi(2) + (b - q).powi(2) + (c - q).powi(2) + 2.0 * p1;
    if p2.is_nan() || p2 <= f64::EPSILON * f64::EPSILON * q * q {
        return [q; 3];
    }
    let p = (p2 / 6.0).sqrt();
    let bm = (m - DMat3::from_diagonal(DVec3::splat(q))) * (1.0 / p);
    let r = (bm.determinant() / 2.0).clamp(-1.0, 1.0);
    let phi = r.acos() / 3.0;
    let hi = q + 2.0 * p * phi.cos();
    let lo = q + 2.0 * p * (phi + 2.0 * std::f64::consts::PI / 3.0).cos();
    [lo, 3.0 * q - hi - lo, hi]
}

/// [`pseudo_inverse_times`] from the Jacobi eigen-decomposition (slower; every case).
fn pseudo_inverse_jacobi(m: DMat3, rhs: DVec3) -> DVec3 {
    let (values, vectors) = symmetric_eigen(m);
    let top = values.abs().max_element();
    let mut x = DVec3::ZERO;
    for k in 0..3 {
        if top > 0.0 && values[k].abs() > EIGEN_CUTOFF * top {
            let v = vectors.col(k);
            x += v * (v.dot(rhs) / values[k]);
        }
    }
    x
}

/// The largest eigenvalue of the positive semi-definite `m` (an `AᵀA`) and its unit eigenvector,
/// when the other two eigenvalues together are at most half the cutoff of the pseudo-inverse
/// (relative to it): the pseudo-inverse then keeps this one direction only. `None` otherwise.
///
/// Most cells of a smooth surface are like this (their normals differ by the curvature over one
/// cell), and this costs a fraction of the Jacobi rotations. Power iteration with `m⁴`: each step
/// shrinks the error angle by `(λ₂/λ₁)⁴ ≤ 10⁻⁸` where the test passes. The test is sound whether
/// or not the iteration settled: the Rayleigh quotient of any unit vector is at most `λ₁`, so
/// `trace − quotient` bounds `λ₂ + λ₃` from above.
fn dominant(m: DMat3) -> Option<(f64, DVec3)> {
    let diag = DVec3::new(m.x_axis.x, m.y_axis.y, m.z_axis.z);
    let trace = diag.element_sum();
    if !(trace > 0.0 && trace.is_finite()) {
        return None;
    }
    // The column of the largest diagonal entry leans at least `1/√3` towards the top direction.
    let start = if diag.x >= diag.y && diag.x >= diag.z {
        m.x_axis
    } else if diag.y >= diag.z {
        m.y_axis
    } else {
        m.z_axis
    };
    let m2 = m * m;
    let m4 = m2 * m2;
    let mut v = start;
    for _ in 0..2 {
        v = (m4 * v).normalize_or_zero();
    }
    let value = v.dot(m * v);
    (value > 0.0 && trace - value <= 0.5 * EIGEN_CUTOFF * value).then_some((value, v))
}

/// Eigenvalues and eigenvectors (columns) of a symmetric 3×3 matrix, by cyclic Jacobi rotations.
pub(crate) fn symmetric_eigen(m: DMat3) -> (DVec3, DMat3) {
    let mut a = [
        [m.x_axis.x, m.y_axis.x, m.z_axis.x],
        [m.x_axis.y, m.y_axis.y, m.z_axis.y],
        [m.x_axis.z, m.y_axis.z, m.z_axis.z],
    ];
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _sweep in 0..12 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        let diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if off <= 1e-30 * diag || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for row in &mut a {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (rp, rq) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * rp[k] - s * rq[k];
                a[q][k] = s * rp[k] + c * rq[k];
            }
            for row in &mut v {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
        }
    }
    let values = DVec3::new(a[0][0], a[1][1], a[2][2]);
    let vectors = DMat3::from_cols(
        DVec3::new(v[0][0], v[1][0], v[2][0]),
        DVec3::new(v[0][1], v[1][1], v[2][1]),
        DVec3::new(v[0][2], v[1][2], v[2][2]),
    );
    (values, vectors)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_decomposition_reconstructs_the_matrix() {
        let m = DMat3::from_cols(
            DVec3::new(4.0, 1.0, -2.0),
            DVec3::new(1.0, 3.0, 0.5),
            DVec3::new(-2.0, 0.5, 1.0),
        );
        let (l, v) = symmetric_eigen(m);
        let back = v * DMat3::from_diagonal(l) * v.transpose();
        for c in 0..3 {
            assert!((back.col(c) - m.col(c)).length() < 1e-12);
        }
        assert!((v.transpose() * v - DMat3::IDENTITY).col(0).length() < 1e-12);
    }

    /// The one-direction shortcut gives the full decomposition's answer wherever it applies, and
    /// declines where a second direction passes the cutoff (random bundles of normals around an
    /// axis, from nearly parallel to widely spread, and sums of two such bundles).
    #[test]
    fn dominant_direction_agrees_with_the_decomposition() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let (mut taken, mut declined) = (0, 0);
        for case in 0..20_000 {
            let spread = [1e-4, 1e-2, 0.05, 0.1, 0.2, 0.5, 1.0][case % 7];
            let axis = DVec3::new(next(), next(), next()).normalize_or(DVec3::Z);
            let mut q = Qef::new(DVec3::ZERO);
            for k in 0..3 + case % 6 {
                let mut n = axis + spread * DVec3::new(next(), next(), next());
                if case % 5 == 0 && k % 2 == 1 {
                    n = n.cross(DVec3::X); // a second bundle: a crease
                }
                let n = n.normalize_or(DVec3::Y);
                q.add(DVec3::new(next(), next(), next()), n);
            }
            let m = q.matrix();
            let rhs = q.atb - m * (q.mass / f64::from(q.count));
            let full = pseudo_inverse_times(m, rhs);
            match dominant(m) {
                Some((value, v)) => {
                    taken += 1;
                    let (values, _) = symmetric_eigen(m);
                    let mut sorted = values.to_array().map(f64::abs);
                    sorted.sort_by(f64::total_cmp);
                    assert!(sorted[1] <= EIGEN_CUTOFF * sorted[2], "{values}");
                    assert!((value - sorted[2]).abs() <= 1e-12 * sorted[2]);
                    let x = v * (v.dot(rhs) / value);
                    assert!(
                        (x - full).length() <= 1e-9 * (1.0 + full.length()),
                        "{x} {full}"
                    );
                }
                None => declined += 1,
            }
        }
        assert!(taken > 5_000 && declined > 5_000, "{taken} {declined}");
    }

    /// The closed-form pseudo-inverse gives the Jacobi decomposition's answer for matrices of
    /// every rank: eigenvalues far apart, equal pairs, triples, zeros, just above and below the
    /// cutoff (not within 10⁻⁶ of it, where the two may keep different directions).
    #[test]
    fn closed_form_pseudo_inverse_agrees_with_jacobi() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let levels = [
            0.0, 1e-12, 1e-4, 0.01, 0.019, 0.021, 0.05, 0.3, 0.5, 0.5, 0.9, 1.0, 1.0,
        ];
        let mut ranks = [0usize; 4];
        for case in 0..30_000 {
            let axis = DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5).normalize_or(DVec3::Z);
            let turn = glam::DQuat::from_axis_angle(axis, 7.0 * next());
            let pick = |r: f64| levels[(r * levels.len() as f64) as usize % levels.len()];
            let scale = [1e-3, 1.0, 12.0, 400.0][case % 4];
            let l = DVec3::new(1.0, pick(next()), pick(next())) * scale;
            let r = DMat3::from_quat(turn);
            let m = r * DMat3::from_diagonal(l) * r.transpose();
            let rhs = DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * scale;
            let want = pseudo_inverse_jacobi(m, rhs);
            let got = pseudo_inverse_times(m, rhs);
            let rank = 1 + [l.y, l.z]
                .iter()
                .filter(|&&x| x > EIGEN_CUTOFF * scale)
                .count();
            ranks[rank] += 1;
            assert!(
                (got - want).length() <= 1e-7 * (1.0 + want.length()),
                "{l} {rhs}: {got} against {want}"
            );
        }
        assert!(
            ranks[1] > 3_000 && ranks[2] > 3_000 && ranks[3] > 3_000,
            "{ranks:?}"
        );
    }

    /// Three planes through a corner give the corner exactly; two give a point on their line
    /// nearest the mass point; one gives the mass point projected onto the plane.
    #[test]
    fn corners_edges_and_planes() {
        let corner = DVec3::new(0.3, -0.2, 0.7);
        let r = glam::DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
        let axes = [r * DVec3::X, r * DVec3::Y, r * DVec3::Z];
        let mut q = Qef::new(DVec3::ZERO);
        for (k, n) in axes.iter().enumerate() {
            let t = axes[(k + 1) % 3] * 0.1 + axes[(k + 2) % 3] * 0.05;
            q.add(corner + t, *n);
        }
        let (x, e) = q.solve(DVec3::splat(-10.0), DVec3::splat(10.0));
        assert!((x - corner).length() < 1e-12 && e < 1e-20);
        // Shifting and merging keep the function.
        let s = q.shifted(DVec3::new(5.0, 1.0, -3.0));
        let probe = DVec3::new(0.1, 0.2, 0.3);
        assert!((s.error(probe) - q.error(probe)).abs() < 1e-9);
        let mut m = Qef::new(DVec3::ONE);
        m.merge(&q);
        m.merge(&q);
        assert!((m.error(probe) - 2.0 * q.error(probe)).abs() < 1e-9);
        let mut flat = Qef::new(DVec3::ZERO);
        flat.add(DVec3::new(0.0, 0.0, 0.5), DVec3::Z);
        flat.add(DVec3::new(1.0, 0.0, 0.5), DVec3::Z);
        let (x, _) = flat.solve(DVec3::splat(-1.0), DVec3::splat(2.0));
        assert!((x - DVec3::new(0.5, 0.0, 0.5)).length() < 1e-12);
    }
}
