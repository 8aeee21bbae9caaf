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
    /// A curve that takes an exact number of points got another number.
    #[error("{parameter}: expected exactly {expected} points, found {found}")]
    PointCount {
        /// The key holding the points.
        parameter: &'static str,
        /// How many the curve takes.
        expected: usize,
        /// How many were given.
        found: usize,
    },
    /// The number of tangents differs from the number of points.
    #[error("tangents: expected {expected} tangents (one per point), found {found}")]
    TangentCount {
        /// The number of points.
        expected: usize,
        /// The number of tangents given.
        found: usize,
    },
    /// A composite curve's pieces do not join as declared.
    #[error("pieces[{index}]: {problem}")]
    Join {
        /// Index of the piece that starts at the bad joint.
        index: usize,
        /// What does not hold, with the measured values.
        problem: String,
    },
    /// A coordinate formula of a formula curve does not parse.
    #[error("{parameter}: {message}")]
    Formula {
        /// The key of the formula (`x`, `y` or `z`).
        parameter: &'static str,
        /// The parser's message (with the column).
        message: String,
    },
    /// The parameter interval `[u0, u1]` is empty or not finite.
    #[error("domain: expected finite [u0, u1] with u0 < u1")]
    Domain,
    /// The chord error asked for needs more polyline points than allowed.
    #[error("chord_error: {tolerance:e} needs more than {limit} polyline points")]
    TooManyPoints {
        /// The chord error asked for.
        tolerance: f64,
        /// The largest number of points produced.
        limit: usize,
    },
    /// The chord error is not a positive finite number.
    #[error("chord_error: expected a positive number, found {0}")]
    BadTolerance(f64),
    /// A piece of a composite curve is itself composite.
    #[error("pieces[{index}]: a composite curve cannot contain another composite curve")]
    NestedComposite {
        /// Index of the nested piece.
        index: usize,
    },
}

impl CurveError {
    /// The JSON key of the curve object this error is about.
    pub fn parameter(&self) -> &'static str {
        match self {
            CurveError::TooFewPoints { parameter, .. }
            | CurveError::PointCount { parameter, .. }
            | CurveError::NonFinite { parameter }
            | CurveError::Formula { parameter, .. } => parameter,
            CurveError::Domain => "domain",
            CurveError::TooManyPoints { .. } | CurveError::BadTolerance(_) => "chord_error",
            CurveError::BadDegree { .. } => "degree",
            CurveError::KnotCount { .. }
            | CurveError::KnotsDecreasing { .. }
            | CurveError::KnotMultiplicity { .. }
            | CurveError::EmptyDomain => "knots",
            CurveError::WeightCount { .. } | CurveError::NonPositiveWeight { .. } => "weights",
            CurveError::TangentCount { .. } => "tangents",
            CurveError::Join { .. } | CurveError::NestedComposite { .. } => "pieces",
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
