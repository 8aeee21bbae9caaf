//! Typed indices of vertices, half-edges and faces, so the three cannot be mixed up.

/// Defines a `u32` index newtype with `index()` and conversions.
macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $name(pub u32);

        impl $name {
            /// The index as `usize`, for indexing arrays.
            pub fn index(self) -> usize {
                self.0 as usize
            }
        }

        impl From<$name> for usize {
            fn from(id: $name) -> usize {
                id.index()
            }
        }
    };
}

id_type!(
    /// A vertex of a [`HalfEdgeMesh`](super::HalfEdgeMesh): index into its positions.
    VertexId
);
id_type!(
    /// A half-edge of a [`HalfEdgeMesh`](super::HalfEdgeMesh).
    HalfEdgeId
);
id_type!(
    /// A face of a [`HalfEdgeMesh`](super::HalfEdgeMesh): index into the input faces.
    FaceId
);
