//! Why a height field cannot be built or loaded.

use crate::primitive::PrimitiveError;

/// A height field that cannot be built or loaded.
#[derive(Debug, thiserror::Error)]
pub enum HeightFieldError {
    /// A scalar parameter is invalid.
    #[error(transparent)]
    Parameter(#[from] PrimitiveError),
    /// Fewer than 2 × 2 heights.
    #[error("heights: need at least 2 × 2 values, got {nx} × {ny}")]
    GridTooSmall {
        /// Columns given.
        nx: usize,
        /// Rows given.
        ny: usize,
    },
    /// The value count does not match the size.
    #[error("heights: {nx} × {ny} grid needs {} values, got {len}", nx * ny)]
    GridShape {
        /// Columns.
        nx: usize,
        /// Rows.
        ny: usize,
        /// Values given.
        len: usize,
    },
    /// Rows of different lengths.
    #[error("heights: row {row} has {len} values, expected {expected}")]
    RaggedRows {
        /// The first bad row.
        row: usize,
        /// Its length.
        len: usize,
        /// The first row's length.
        expected: usize,
    },
    /// A Bézier net whose evaluation costs too much per point.
    #[error(
        "a {nx} × {ny} Bézier control net costs {} multiply-adds at every evaluated point (at most \
         {} control heights, e.g. 64 × 64); give dense height data as \"samples\" (bicubic for a \
         smooth surface), which cost the same at any size",
        nx * ny,
        super::MAX_CONTROL_HEIGHTS
    )]
    TooManyControlHeights {
        /// Columns given.
        nx: usize,
        /// Rows given.
        ny: usize,
    },
    /// A NaN or infinite height.
    #[error("heights: value at column {column}, row {row} is not finite")]
    NonFinite {
        /// Column of the first bad value.
        column: usize,
        /// Row of the first bad value.
        row: usize,
    },
    /// The height map file cannot be read.
    #[error("cannot read height map {0}")]
    Io(#[from] crate::files::FileError),
    /// The height map file cannot be read; the reason comes from a
    /// [`MeshResolver`](crate::primitive::MeshResolver).
    #[error("cannot read height map {path:?}: {reason}")]
    Unreadable {
        /// The path as written.
        path: String,
        /// Why not.
        reason: crate::primitive::ResolveError,
    },
    /// The image declares more pixels than a height map may have.
    #[error(
        "PNG height map of {width} × {height} pixels is too large (at most {} pixels a side and {} pixels in all)",
        super::MAX_PNG_SIDE,
        super::MAX_PNG_PIXELS
    )]
    ImageTooLarge {
        /// Declared width.
        width: u32,
        /// Declared height.
        height: u32,
    },
    /// The PNG data is malformed.
    #[error("cannot decode PNG height map: {0}")]
    Png(#[from] png::DecodingError),
    /// The PNG is not a grayscale image.
    #[error("PNG height map must be grayscale (8 or 16 bits), found {color:?} at {bits} bits")]
    NotGrayscale {
        /// The image's color type.
        color: png::ColorType,
        /// Bits per sample.
        bits: u8,
    },
}
