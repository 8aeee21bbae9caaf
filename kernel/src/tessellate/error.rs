//! Why a tessellation cannot be made.

/// A tessellation request that cannot be met.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TessellationError {
    /// A sample count is out of range.
    #[error("{what} must be between {min} and {max}, got {got}")]
    Count {
        /// Which count.
        what: &'static str,
        /// Given.
        got: usize,
        /// Smallest allowed.
        min: usize,
        /// Largest allowed.
        max: usize,
    },
    /// A count that must be odd is even.
    #[error("{what} must be odd, got {got}")]
    Even {
        /// Which count.
        what: &'static str,
        /// Given.
        got: usize,
    },
    /// A size parameter is not a positive finite number.
    #[error("{0}: expected a positive finite number")]
    NotPositive(&'static str),
}

/// Largest sample count along one parameter direction.
pub const MAX_SAMPLES: usize = 1 << 14;

/// Checks `min ≤ n ≤ MAX_SAMPLES`.
pub(crate) fn count(what: &'static str, n: usize, min: usize) -> Result<(), TessellationError> {
    if n < min || n > MAX_SAMPLES {
        Err(TessellationError::Count {
            what,
            got: n,
            min,
            max: MAX_SAMPLES,
        })
    } else {
        Ok(())
    }
}

/// Checks that `x` is positive and finite.
pub(crate) fn positive(what: &'static str, x: f64) -> Result<(), TessellationError> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(TessellationError::NotPositive(what))
    }
}
