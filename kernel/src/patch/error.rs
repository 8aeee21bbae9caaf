//! Why a patch or a patch tessellation cannot be built.

/// A patch or tessellation input that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PatchError {
    /// The control net has the wrong number of points for its degree.
    #[error("control net of degree {degree} needs {expected} points, got {got}")]
    ControlCount {
        /// The degree.
        degree: usize,
        /// Points needed.
        expected: usize,
        /// Points given.
        got: usize,
    },
    /// A control point or normal is not finite.
    #[error("{what} {index} is not finite")]
    NonFinite {
        /// "control point", "vertex" or "normal".
        what: &'static str,
        /// Its index.
        index: usize,
    },
    /// A triangle refers to a vertex that does not exist.
    #[error("triangle {triangle} refers to vertex {vertex}, but there are {count} vertices")]
    IndexOutOfRange {
        /// The triangle.
        triangle: usize,
        /// The bad index.
        vertex: u32,
        /// Vertex count.
        count: usize,
    },
    /// The normals do not match the vertices.
    #[error("{normals} normals for {vertices} vertices")]
    NormalCount {
        /// Normals given.
        normals: usize,
        /// Vertices.
        vertices: usize,
    },
    /// A vertex normal has zero length (no triangle gives it a direction, or one was given).
    #[error("vertex {0} has no normal direction")]
    ZeroNormal(usize),
    /// A tessellation count is out of range.
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
}
