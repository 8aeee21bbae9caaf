//! What a [`MeshResolver`](super::MeshResolver) is asked to subdivide: the scheme, the polygon
//! mesh and the number of levels of one `subdivide` node.

use glam::DVec3;

/// A subdivision scheme, by its JSON name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SubdivisionScheme {
    /// Catmull-Clark: any polygon mesh to quads; approximating (`"catmull-clark"`).
    CatmullClark,
    /// Loop: triangle meshes; approximating (`"loop"`).
    Loop,
    /// Modified butterfly (Zorin et al.): triangle meshes; interpolating (`"butterfly"`).
    Butterfly,
    /// Doo-Sabin: the dual scheme, any polygon mesh (`"doo-sabin"`).
    DooSabin,
}

impl SubdivisionScheme {
    /// Every scheme, in the order of the documentation.
    pub const ALL: [SubdivisionScheme; 4] = [
        SubdivisionScheme::CatmullClark,
        SubdivisionScheme::Loop,
        SubdivisionScheme::Butterfly,
        SubdivisionScheme::DooSabin,
    ];

    /// The name in JSON trees and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            SubdivisionScheme::CatmullClark => "catmull-clark",
            SubdivisionScheme::Loop => "loop",
            SubdivisionScheme::Butterfly => "butterfly",
            SubdivisionScheme::DooSabin => "doo-sabin",
        }
    }

    /// The scheme called `name` (exactly as [`SubdivisionScheme::name`] writes it).
    pub fn from_name(name: &str) -> Option<SubdivisionScheme> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }

    /// True for the schemes that need a triangle mesh (Loop, butterfly).
    pub fn needs_triangles(self) -> bool {
        matches!(self, SubdivisionScheme::Loop | SubdivisionScheme::Butterfly)
    }
}

impl std::fmt::Display for SubdivisionScheme {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The polygon mesh a resolver is asked to subdivide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SubdivisionInput<'a> {
    /// Vertices and polygonal faces (counter-clockwise seen from outside).
    Faces {
        /// Vertex positions.
        vertices: &'a [DVec3],
        /// Faces as vertex indices.
        faces: &'a [Vec<u32>],
    },
    /// The mesh file of a `mesh` node, by the path written in the tree; the resolver reads it
    /// with its polygonal faces (an OBJ or OFF of quads stays quads).
    File {
        /// The path as written in the tree.
        path: &'a str,
    },
}

/// One `subdivide` request: what, how and how often.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SubdivisionRequest<'a> {
    /// The polygon mesh of the child node.
    pub input: SubdivisionInput<'a>,
    /// The scheme.
    pub scheme: SubdivisionScheme,
    /// How many times to apply it (adaptive: at most).
    pub levels: u32,
    /// Adaptive subdivision: refine only where the next level moves off a face by more than
    /// this distance (Loop and Catmull-Clark); `None`: uniform.
    pub adaptive: Option<f64>,
}
