//! Why a distance cannot be measured.

/// A mesh that distance queries cannot use.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MeasureError {
    /// No triangle with three distinct in-range indices: there is no surface to measure against.
    #[error("the mesh has no usable triangles (no surface to measure distances to)")]
    NoSurface,
    /// A vertex used by a triangle has a NaN or infinite coordinate.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFiniteVertex {
        /// The vertex index.
        vertex: usize,
    },
    /// More triangles than the tree's 32-bit primitive ids can address.
    #[error("mesh too large: {count} triangles exceed the 32-bit id range")]
    TooLarge {
        /// Number of triangles.
        count: usize,
    },
}
