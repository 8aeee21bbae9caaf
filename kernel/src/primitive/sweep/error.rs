//! Why a sweep primitive's parameters make no solid, or why it cannot be tessellated. Each error
//! names the key of the primitive's JSON object it is about (and the nested key inside a profile
//! or curve object).

use crate::curve::CurveError;
use crate::profile::ProfileError;

/// A sweep primitive that cannot be built or tessellated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    /// The profile (under `key`: `profile`, `bottom` or `top`) is invalid.
    #[error("{key}.{}", .error)]
    Profile {
        /// The primitive's key holding the profile.
        key: &'static str,
        /// What is wrong with it.
        error: ProfileError,
    },
    /// A curve (under `key`: `path`, `bottom` or `top`) is invalid.
    #[error("{key}.{}", .error)]
    Curve {
        /// The primitive's key holding the curve.
        key: &'static str,
        /// What is wrong with it.
        error: CurveError,
    },
    /// A parameter of the primitive itself is invalid.
    #[error("{parameter}: {problem}")]
    Invalid {
        /// The key of the bad parameter.
        parameter: &'static str,
        /// What is wrong.
        problem: &'static str,
    },
}

impl SweepError {
    /// The key of the primitive's JSON object this error is about.
    pub fn parameter(&self) -> &'static str {
        match self {
            SweepError::Profile { key, .. } | SweepError::Curve { key, .. } => key,
            SweepError::Invalid { parameter, .. } => parameter,
        }
    }

    /// The key inside the nested profile or curve object, if the error is about one.
    pub fn nested_parameter(&self) -> Option<&'static str> {
        match self {
            SweepError::Profile { error, .. } => Some(error.parameter()),
            SweepError::Curve { error, .. } => Some(error.parameter()),
            SweepError::Invalid { .. } => None,
        }
    }
}

/// An error about the primitive's own parameter.
pub(crate) fn invalid(parameter: &'static str, problem: &'static str) -> SweepError {
    SweepError::Invalid { parameter, problem }
}

/// Checks that `x` is finite and positive.
pub(crate) fn positive(parameter: &'static str, x: f64) -> Result<(), SweepError> {
    if !x.is_finite() {
        Err(invalid(parameter, "expected a finite number"))
    } else if x <= 0.0 {
        Err(invalid(parameter, "expected a positive number"))
    } else {
        Ok(())
    }
}
