//! How a quadric is given: the general ten coefficients, or one of the named quadrics with its
//! natural parameters in its canonical frame (axis along z, centre or apex at the origin). The
//! inside is always `Q ≤ 0` for the `Q` written below each variant.

use super::super::{PrimitiveError, positive};
use super::classify::QuadricKind;
use super::coefficients::QuadricCoefficients;

/// A quadric given by coefficients or by name; see each variant for its `Q` (inside `Q ≤ 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum QuadricForm {
    /// Any quadric by its ten coefficients.
    General(QuadricCoefficients),
    /// `x²/a² + y²/b² − 1`: the solid elliptic cylinder along z.
    EllipticCylinder {
        /// Semi-axes `[a, b]` of the cross-section.
        radii: [f64; 2],
    },
    /// `x²/a² + y²/b² − z²`: the solid double cone along z with its apex at the origin; its
    /// cross-section at height `z` has semi-axes `a|z|`, `b|z|`.
    EllipticCone {
        /// Semi-axes `[a, b]` of the cross-section at `z = ±1`.
        radii: [f64; 2],
    },
    /// `x²/a² + y²/b² − z`: the solid above the paraboloid `z = x²/a² + y²/b²`.
    EllipticParaboloid {
        /// Semi-axes `[a, b]` of the cross-section at `z = 1`.
        radii: [f64; 2],
    },
    /// `x²/a² − y²/b² − z`: the solid above the saddle `z = x²/a² − y²/b²`.
    HyperbolicParaboloid {
        /// Scales `[a, b]` of the two parabolas.
        radii: [f64; 2],
    },
    /// `x²/a² + y²/b² − z²/c² − 1`: the solid inside the hyperboloid of one sheet (around z).
    HyperboloidOfOneSheet {
        /// Semi-axes `[a, b]` of the waist ellipse and the scale `c` along z.
        radii: [f64; 3],
    },
    /// `x²/a² + y²/b² − z²/c² + 1`: the two solid caps inside the sheets, `|z| ≥ c`.
    HyperboloidOfTwoSheets {
        /// Scales `[a, b]` across and the vertex height `c`.
        radii: [f64; 3],
    },
}

impl QuadricForm {
    /// The node type in the JSON tree format.
    pub fn name(&self) -> &'static str {
        match self {
            Self::General(_) => "quadric",
            Self::EllipticCylinder { .. } => "elliptic_cylinder",
            Self::EllipticCone { .. } => "elliptic_cone",
            Self::EllipticParaboloid { .. } => "elliptic_paraboloid",
            Self::HyperbolicParaboloid { .. } => "hyperbolic_paraboloid",
            Self::HyperboloidOfOneSheet { .. } => "hyperboloid_one_sheet",
            Self::HyperboloidOfTwoSheets { .. } => "hyperboloid_two_sheets",
        }
    }

    /// The surface type a named form always has (`None` for general coefficients).
    pub fn named_kind(&self) -> Option<QuadricKind> {
        Some(match self {
            Self::General(_) => return None,
            Self::EllipticCylinder { .. } => QuadricKind::EllipticCylinder,
            Self::EllipticCone { .. } => QuadricKind::Cone,
            Self::EllipticParaboloid { .. } => QuadricKind::EllipticParaboloid,
            Self::HyperbolicParaboloid { .. } => QuadricKind::HyperbolicParaboloid,
            Self::HyperboloidOfOneSheet { .. } => QuadricKind::HyperboloidOfOneSheet,
            Self::HyperboloidOfTwoSheets { .. } => QuadricKind::HyperboloidOfTwoSheets,
        })
    }

    /// The natural parameters of a named form (`radii`), empty for general coefficients.
    pub fn radii(&self) -> &[f64] {
        match self {
            Self::General(_) => &[],
            Self::EllipticCylinder { radii }
            | Self::EllipticCone { radii }
            | Self::EllipticParaboloid { radii }
            | Self::HyperbolicParaboloid { radii } => radii,
            Self::HyperboloidOfOneSheet { radii } | Self::HyperboloidOfTwoSheets { radii } => radii,
        }
    }

    /// Checks the parameters (finite coefficients, positive radii).
    pub fn validate(&self) -> Result<(), PrimitiveError> {
        match self {
            Self::General(c) => c.validate(),
            _ => self.radii().iter().try_for_each(|&r| positive("radii", r)),
        }
    }

    /// The ten coefficients of this form's `Q`.
    pub fn coefficients(&self) -> QuadricCoefficients {
        let inv2 = |r: f64| 1.0 / (r * r);
        let zero = QuadricCoefficients::default();
        match *self {
            Self::General(c) => c,
            Self::EllipticCylinder { radii: [a, b] } => QuadricCoefficients {
                a: inv2(a),
                b: inv2(b),
                d: -1.0,
                ..zero
            },
            Self::EllipticCone { radii: [a, b] } => QuadricCoefficients {
                a: inv2(a),
                b: inv2(b),
                c: -1.0,
                ..zero
            },
            Self::EllipticParaboloid { radii: [a, b] } => QuadricCoefficients {
                a: inv2(a),
                b: inv2(b),
                r: -0.5,
                ..zero
            },
            Self::HyperbolicParaboloid { radii: [a, b] } => QuadricCoefficients {
                a: inv2(a),
                b: -inv2(b),
                r: -0.5,
                ..zero
            },
            Self::HyperboloidOfOneSheet { radii: [a, b, c] } => QuadricCoefficients {
                a: inv2(a),
                b: inv2(b),
                c: -inv2(c),
                d: -1.0,
                ..zero
            },
            Self::HyperboloidOfTwoSheets { radii: [a, b, c] } => QuadricCoefficients {
                a: inv2(a),
                b: inv2(b),
                c: -inv2(c),
                d: 1.0,
                ..zero
            },
        }
    }
}
