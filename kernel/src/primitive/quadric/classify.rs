//! Classification of a quadric surface `Q = 0` into its type; the method is documented on
//! [`classify`].

use super::coefficients::QuadricCoefficients;
use super::eigen::symmetric_eigen;
use glam::DVec3;

/// The type of a quadric surface, following the classical 17-entry table plus the degenerate
/// linear and constant cases. "Imaginary" types have no real point.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum QuadricKind {
    /// ρ3 = 3, ρ4 = 4, Δ < 0, k = 1.
    Ellipsoid,
    /// ρ3 = 3, ρ4 = 4, Δ > 0, k = 1: no real point.
    ImaginaryEllipsoid,
    /// ρ3 = 3, ρ4 = 4, Δ > 0, k = 0.
    HyperboloidOfOneSheet,
    /// ρ3 = 3, ρ4 = 4, Δ < 0, k = 0.
    HyperboloidOfTwoSheets,
    /// ρ3 = 3, ρ4 = 3, k = 0: a real (elliptic) cone.
    Cone,
    /// ρ3 = 3, ρ4 = 3, k = 1: an imaginary cone, whose only real point is its apex.
    Point,
    /// ρ3 = 2, ρ4 = 4, Δ < 0, k = 1.
    EllipticParaboloid,
    /// ρ3 = 2, ρ4 = 4, Δ > 0, k = 0.
    HyperbolicParaboloid,
    /// ρ3 = 2, ρ4 = 3, k = 1, k' = 0.
    EllipticCylinder,
    /// ρ3 = 2, ρ4 = 3, k = 1, k' = 1: no real point.
    ImaginaryEllipticCylinder,
    /// ρ3 = 2, ρ4 = 3, k = 0.
    HyperbolicCylinder,
    /// ρ3 = 2, ρ4 = 2, k = 0: two planes crossing along a line.
    IntersectingPlanes,
    /// ρ3 = 2, ρ4 = 2, k = 1: imaginary intersecting planes, whose real points form a line.
    Line,
    /// ρ3 = 1, ρ4 = 3.
    ParabolicCylinder,
    /// ρ3 = 1, ρ4 = 2, k' = 0.
    ParallelPlanes,
    /// ρ3 = 1, ρ4 = 2, k' = 1: no real point.
    ImaginaryParallelPlanes,
    /// ρ3 = 1, ρ4 = 1: one plane counted twice.
    CoincidentPlanes,
    /// ρ3 = 0, ρ4 = 2: `Q` is linear.
    Plane,
    /// ρ3 = 0, ρ4 ≤ 1: `Q` is constant, so there is no surface.
    Constant,
}

impl QuadricKind {
    /// True for the types whose zero set has no real point.
    pub fn is_imaginary(self) -> bool {
        matches!(
            self,
            Self::ImaginaryEllipsoid
                | Self::ImaginaryEllipticCylinder
                | Self::ImaginaryParallelPlanes
                | Self::Constant
        )
    }
}

/// The invariants of the classification table and the canonical data behind them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Classification {
    /// The surface type.
    pub kind: QuadricKind,
    /// Eigenvalues of `A`, ascending.
    pub eigenvalues: DVec3,
    /// `rank A` (ρ3).
    pub rank3: u8,
    /// `rank E` (ρ4).
    pub rank4: u8,
    /// Sign of `det E`: −1, 0 or +1.
    pub det_sign: i8,
}

/// Classifies the quadric `Q = 0`.
///
/// # Method
/// The classical table (e.g. Beyer, *CRC Standard Mathematical Tables*) names a real quadric from
/// four invariants of `A` (the 3×3 part) and `E = [[A, l], [lᵀ, d]]` (the 4×4 matrix):
/// `ρ3 = rank A`, `ρ4 = rank E`, the sign of `Δ = det E`, and whether the nonzero eigenvalues of `A`
/// (resp. `E`) share one sign (`k`, resp. `k'`).
///
/// Ranks of `E` computed naively mix units (`A` ~ 1/length², `l` ~ 1/length, `d` ~ 1) and break
/// under large translations, so `E` is first brought to block-diagonal form by a congruence, which
/// by Sylvester's law of inertia keeps its rank and the signs of its eigenvalues (hence the sign of
/// `Δ`, `k'`):
/// 1. `A = V Λ Vᵀ` (Jacobi); in the rotated frame `Q = Σ λ_i x_i² + 2 Σ l'_i x_i + d`, `l' = Vᵀl`.
/// 2. For each `λ_i ≠ 0`, complete the square: `d' = d − Σ_{λ_i ≠ 0} l'_i² / λ_i`.
/// 3. What is left in the kernel of `A` is a linear part `β` (the `l'_i` with `λ_i = 0`).
///
/// `E` is then congruent to `diag(λ_nonzero) ⊕ [[0, β], [βᵀ, d']]`, so `ρ4 = ρ3 + 2` when `β ≠ 0`,
/// else `ρ3 + (d' ≠ 0)`, and `sign Δ = sign(Π λ · d')` for `ρ3 = 3`, `−sign(Π λ)` for `ρ3 = 2`,
/// `β ≠ 0`. Zero tests are relative: `|λ| ≤ 10⁻¹⁰ max|λ|`, `|β| ≤ 10⁻¹⁰ |l|`, and
/// `|d'| ≤ 10⁻¹⁰ (|d| + Σ l'_i²/|λ_i|)` (the size of what cancelled).
pub fn classify(q: &QuadricCoefficients) -> Classification {
    let (lambda, v) = symmetric_eigen(q.matrix3());
    let lp = v.transpose() * q.linear();
    let max_abs = lambda.abs().max_element();
    let nonzero = [0, 1, 2].map(|i| max_abs > 0.0 && lambda[i].abs() > 1e-10 * max_abs);
    let rank3 = nonzero.iter().filter(|&&n| n).count() as u8;
    let (mut d_prime, mut cancelled) = (q.d, q.d.abs());
    let mut beta2 = 0.0;
    for i in 0..3 {
        if nonzero[i] {
            let t = lp[i] * lp[i] / lambda[i];
            d_prime -= t;
            cancelled += t.abs();
        } else {
            beta2 += lp[i] * lp[i];
        }
    }
    let beta_nonzero = beta2.sqrt() > 1e-10 * q.linear().length() && beta2 > 0.0;
    let d_nonzero = d_prime.abs() > 1e-10 * cancelled && d_prime != 0.0;
    let nz: Vec<f64> = (0..3).filter(|&i| nonzero[i]).map(|i| lambda[i]).collect();
    let positives = nz.iter().filter(|&&x| x > 0.0).count();
    let same_sign = positives == 0 || positives == nz.len(); // k
    let lambda_sign = nz.iter().fold(1.0, |acc, x| acc * x.signum());
    // Does d' have the sign opposite to the (common) sign of the eigenvalues? (k' = 0 cases.)
    let opposite = same_sign && !nz.is_empty() && d_prime.signum() != nz[0].signum();
    let (rank4, det_sign, kind) = match rank3 {
        3 if d_nonzero => {
            let det = (lambda_sign * d_prime.signum()) as i8;
            let kind = if same_sign {
                if opposite {
                    QuadricKind::Ellipsoid
                } else {
                    QuadricKind::ImaginaryEllipsoid
                }
            } else if det > 0 {
                QuadricKind::HyperboloidOfOneSheet
            } else {
                QuadricKind::HyperboloidOfTwoSheets
            };
            (4, det, kind)
        }
        3 => {
            let kind = if same_sign {
                QuadricKind::Point
            } else {
                QuadricKind::Cone
            };
            (3, 0, kind)
        }
        2 if beta_nonzero => {
            let det = (-lambda_sign) as i8;
            let kind = if same_sign {
                QuadricKind::EllipticParaboloid
            } else {
                QuadricKind::HyperbolicParaboloid
            };
            (4, det, kind)
        }
        2 if d_nonzero => {
            let kind = match (same_sign, opposite) {
                (true, true) => QuadricKind::EllipticCylinder,
                (true, false) => QuadricKind::ImaginaryEllipticCylinder,
                (false, _) => QuadricKind::HyperbolicCylinder,
            };
            (3, 0, kind)
        }
        2 => {
            let kind = if same_sign {
                QuadricKind::Line
            } else {
                QuadricKind::IntersectingPlanes
            };
            (2, 0, kind)
        }
        1 if beta_nonzero => (3, 0, QuadricKind::ParabolicCylinder),
        1 if d_nonzero => {
            let kind = if opposite {
                QuadricKind::ParallelPlanes
            } else {
                QuadricKind::ImaginaryParallelPlanes
            };
            (2, 0, kind)
        }
        1 => (1, 0, QuadricKind::CoincidentPlanes),
        _ if beta_nonzero => (2, 0, QuadricKind::Plane),
        _ => (u8::from(d_nonzero), 0, QuadricKind::Constant),
    };
    Classification {
        kind,
        eigenvalues: lambda,
        rank3,
        rank4,
        det_sign,
    }
}
