//! Why a face list cannot become a half-edge mesh.

/// How many offending items of each kind the [`HalfEdgeError::NonManifold`] message shows.
const SHOWN: usize = 4;

/// An input that a half-edge structure cannot represent.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HalfEdgeError {
    /// A face refers to a vertex outside the position array (the first such face and index).
    #[error("face {face} refers to vertex {index}, but there are only {vertex_count} vertices")]
    IndexOutOfRange {
        /// The face, as an index into the input faces.
        face: usize,
        /// The offending vertex index.
        index: u32,
        /// Number of positions.
        vertex_count: usize,
    },
    /// A face has fewer than three vertices or repeats a vertex (the first such face).
    #[error("face {face} is degenerate: fewer than 3 vertices or a repeated vertex")]
    DegenerateFace {
        /// The face, as an index into the input faces.
        face: usize,
    },
    /// The faces do not form an oriented 2-manifold (with boundary). Lists every offender,
    /// sorted and deduplicated; edges are `[smaller vertex, larger vertex]`.
    #[error("{}", non_manifold_message(edges, vertices, inconsistent_edges))]
    NonManifold {
        /// Edges used by more than two faces.
        edges: Vec<[u32; 2]>,
        /// Vertices whose faces form more than one fan (e.g. two cones touching at a tip, or two
        /// boundary loops through one vertex).
        vertices: Vec<u32>,
        /// Edges used by two faces in the same direction (inconsistent orientation).
        inconsistent_edges: Vec<[u32; 2]>,
    },
    /// More vertices, faces or half-edges than 32-bit ids can address.
    #[error("mesh too large: {count} {what} exceed the 32-bit id range")]
    TooLarge {
        /// What overflowed (`"vertices"`, `"faces"` or `"half-edges"`).
        what: &'static str,
        /// How many there are.
        count: usize,
    },
}

/// `non-manifold input: 1 edge used by more than two faces (0-1), ...`.
fn non_manifold_message(edges: &[[u32; 2]], vertices: &[u32], inconsistent: &[[u32; 2]]) -> String {
    let edge_text = |e: &[u32; 2]| format!("{}-{}", e[0], e[1]);
    let parts = [
        part(
            edges.iter().map(edge_text),
            edges.len(),
            "edge(s) used by more than two faces",
        ),
        part(
            vertices.iter().map(u32::to_string),
            vertices.len(),
            "vertex(es) with more than one fan",
        ),
        part(
            inconsistent.iter().map(edge_text),
            inconsistent.len(),
            "edge(s) used twice in the same direction",
        ),
    ];
    let parts: Vec<String> = parts.into_iter().flatten().collect();
    format!("non-manifold input: {}", parts.join("; "))
}

/// `count what (first, second, ...)`, or `None` when `count` is zero.
fn part(items: impl Iterator<Item = String>, count: usize, what: &str) -> Option<String> {
    if count == 0 {
        return None;
    }
    let shown: Vec<String> = items.take(SHOWN).collect();
    let more = if count > SHOWN { ", ..." } else { "" };
    Some(format!("{count} {what} ({}{more})", shown.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::HalfEdgeError;

    #[test]
    fn non_manifold_message_shows_counts_and_first_items() {
        let err = HalfEdgeError::NonManifold {
            edges: (0..6).map(|i| [i, i + 1]).collect(),
            vertices: vec![7],
            inconsistent_edges: vec![],
        };
        assert_eq!(
            err.to_string(),
            "non-manifold input: 6 edge(s) used by more than two faces (0-1, 1-2, 2-3, 3-4, ...); \
             1 vertex(es) with more than one fan (7)"
        );
    }

    #[test]
    fn other_messages() {
        let err = HalfEdgeError::IndexOutOfRange {
            face: 3,
            index: 9,
            vertex_count: 8,
        };
        assert_eq!(
            err.to_string(),
            "face 3 refers to vertex 9, but there are only 8 vertices"
        );
        let err = HalfEdgeError::DegenerateFace { face: 2 };
        assert!(err.to_string().starts_with("face 2 is degenerate"));
    }
}
