//! Half-edge mesh (placeholder until the module lands).

/// Half-edge mesh (placeholder).
#[derive(Debug, Clone, Default)]
pub struct HalfEdgeMesh;
