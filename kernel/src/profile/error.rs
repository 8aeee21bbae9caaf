//! Why a profile's parameters make no region, or why its boundary cannot be triangulated.

use crate::triangulate::TriangulationError;

/// A profile that cannot be used, or a cap that cannot be triangulated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ProfileError {
    /// A number is NaN or infinite.
    #[error("{parameter}: expected finite numbers")]
    NonFinite {
        /// The key holding the bad number.
        parameter: &'static str,
    },
    /// A size or radius is zero or negative.
    #[error("{parameter}: expected a positive number")]
    NotPositive {
        /// The key holding the bad number.
        parameter: &'static str,
    },
    /// A loop has fewer than three corners.
    #[error("{parameter}: a loop needs at least 3 points, found {found}")]
    TooFewPoints {
        /// `points` or `holes`.
        parameter: &'static str,
        /// How many the loop has.
        found: usize,
    },
    /// Two consecutive corners of a loop coincide (a zero-length edge).
    #[error("{parameter}: corners {index} and the next coincide")]
    RepeatedPoint {
        /// `points` or `holes`.
        parameter: &'static str,
        /// Index of the first of the two corners within its loop.
        index: usize,
    },
    /// A loop encloses no area.
    #[error("{parameter}: a loop has zero area")]
    ZeroArea {
        /// `points` or `holes`.
        parameter: &'static str,
    },
    /// The loops cannot be triangulated (they cross or touch, or a loop is degenerate).
    #[error("profile: the loops cannot be triangulated: {problem}")]
    Triangulation {
        /// What is wrong with them.
        problem: TriangulationError,
    },
}

impl ProfileError {
    /// The JSON key of the profile object this error is about.
    pub fn parameter(&self) -> &'static str {
        match self {
            ProfileError::NonFinite { parameter }
            | ProfileError::NotPositive { parameter }
            | ProfileError::TooFewPoints { parameter, .. }
            | ProfileError::RepeatedPoint { parameter, .. }
            | ProfileError::ZeroArea { parameter } => parameter,
            ProfileError::Triangulation { .. } => "points",
        }
    }
}

/// Checks that `x` is finite and positive.
pub(crate) fn positive(parameter: &'static str, x: f64) -> Result<(), ProfileError> {
    if !x.is_finite() {
        Err(ProfileError::NonFinite { parameter })
    } else if x <= 0.0 {
        Err(ProfileError::NotPositive { parameter })
    } else {
        Ok(())
    }
}
