//! Why a curve's parameters make no curve: each error names the JSON key it is about.

/// A curve definition that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CurveError {
    /// Too few points (or control points) for the kind of curve.
    #[error("{parameter}: expected at least {needed} points, found {found}")]
    TooFewPoints {
        /// The key holding the points.
        parameter: &'static str,
        /// How many the curve needs.
        needed: usize,
        /// How many were given.
        found: usize,
    },
    /// A coordinate, knot or weight is NaN or infinite.
    #[error("{parameter}: expected finite numbers")]
    NonFinite {
        /// The key holding the bad number.
        parameter: &'static str,
    },
    /// The degree is zero or too high for the number of control points.
    #[error("degree: {degree} needs between 1 and {max} (one less than the number of points)")]
    BadDegree {
        /// The degree given.
        degree: usize,
        /// The largest degree the control points allow.
        max: usize,
    },
    /// The knot vector has the wrong length.
    #[error("knots: expected {expected} knots (points + degree + 1), found {found}")]
    KnotCount {
        /// points + degree + 1.
        expected: usize,
        /// The number given.
        found: usize,
    },
    /// The knots decrease somewhere.
    #[error("knots: knot {index} is smaller than the one before it")]
    KnotsDecreasing {
        /// Index of the first knot that is smaller than its predecessor.
        index: usize,
    },
    /// An interior knot is repeated more than `degree` times (the curve would break apart).
    #[error("knots: knot {index} is repeated more than the degree allows")]
    KnotMultiplicity {
        /// Index of the first knot of the repeated run.
        index: usize,
    },
    /// The parameter domain `[knots[degree], knots[points]]` has no length.
    #[error("knots: the parameter domain is empty")]
    EmptyDomain,
    /// The number of weights differs from the number of control points.
    #[error("weights: expected {expected} weights (one per point), found {found}")]
    WeightCount {
        /// The number of control points.
        expected: usize,
        /// The number of weights given.
        found: usize,
    },
    /// A weight is zero or negative.
    #[error("weights: weight {index} is not positive")]
    NonPositiveWeight {
        /// Index of the bad weight.
        index: usize,
    },
}

impl CurveError {
    /// The JSON key of the curve object this error is about.
    pub fn parameter(&self) -> &'static str {
        match self {
            CurveError::TooFewPoints { parameter, .. } | CurveError::NonFinite { parameter } => {
                parameter
            }
            CurveError::BadDegree { .. } => "degree",
            CurveError::KnotCount { .. }
            | CurveError::KnotsDecreasing { .. }
            | CurveError::KnotMultiplicity { .. }
            | CurveError::EmptyDomain => "knots",
            CurveError::WeightCount { .. } | CurveError::NonPositiveWeight { .. } => "weights",
        }
    }
}

/// Checks that every coordinate of every point is finite.
pub(crate) fn finite_points(
    parameter: &'static str,
    points: &[glam::DVec3],
) -> Result<(), CurveError> {
    if points.iter().all(|p| p.is_finite()) {
        Ok(())
    } else {
        Err(CurveError::NonFinite { parameter })
    }
}

/// Checks that there are at least `needed` points.
pub(crate) fn enough_points(
    parameter: &'static str,
    found: usize,
    needed: usize,
) -> Result<(), CurveError> {
    if found >= needed {
        Ok(())
    } else {
        Err(CurveError::TooFewPoints {
            parameter,
            needed,
            found,
        })
    }
}
