//! Subdivision surfaces on the [`HalfEdgeMesh`]: Catmull-Clark, Loop, modified butterfly and
//! Doo-Sabin, each applied a given number of levels.
//!
//! | scheme | input | output | kind | counts per level (closed mesh; `E_b` boundary edges) |
//! |---|---|---|---|---|
//! | [`catmull_clark()`] ([rules](mod@catmull_clark)) | any polygons | quads | approximating, primal | V' = V + E + F, E' = 2E + Σdeg, F' = Σdeg |
//! | [`loop_subdivision()`] ([rules](loop_scheme)) | triangles | triangles | approximating, primal | V' = V + E, E' = 2E + 3F, F' = 4F |
//! | [`butterfly()`] ([rules](mod@butterfly)) | triangles | triangles | interpolating, primal | as Loop |
//! | [`doo_sabin()`] ([rules](mod@doo_sabin)) | any polygons | any polygons | approximating, dual | V' = Σdeg, E' = 2Σdeg, F' = F + E + V (open: V' = Σdeg + 2E_b, E' = Σdeg + 2E + 2E_b) |
//!
//! Every level is one pass over the faces, edges and vertices of the previous mesh (loops only, no
//! recursion), producing new positions and face loops from which the next [`HalfEdgeMesh`] is built
//! (`HalfEdgeMesh::from_faces`, which also re-checks the result). Vertex order is stable: primal
//! schemes keep the old vertices first (their new positions, or the same positions bit for bit for
//! the butterfly), then one vertex per edge (edges numbered by their smaller half-edge id), then, for
//! Catmull-Clark, one per face. Open meshes use boundary rules (documented per scheme); isolated
//! vertices stay where they are in the primal schemes and are dropped by Doo-Sabin.
//!
//! [`subdivide_adaptive`] ([rules](adaptive)) refines only the faces that are not yet flat to a
//! tolerance (Loop with red-green closure, Catmull-Clark with conforming polygons), crack-free and
//! manifold.
//!
//! Before any work the face counts of all requested levels are predicted (exactly for the primal
//! schemes, an upper bound for Doo-Sabin); a request above [`Limits::max_faces`] fails with
//! [`SubdivisionError::TooLarge`] instead of exhausting memory.

// The scheme modules are public for their documentation (the rules of each scheme); their
// entry points are the functions below.
pub mod adaptive;
pub mod butterfly;
pub mod catmull_clark;
pub mod doo_sabin;
mod edges;
mod error;
pub mod loop_scheme;
mod split;

#[cfg(test)]
mod adaptive_tests;
#[cfg(test)]
mod tests;

pub use adaptive::{AdaptiveLevel, subdivide_adaptive};
pub use error::SubdivisionError;
pub use solidkit_kernel::primitive::SubdivisionScheme as Scheme;

use crate::HalfEdgeMesh;

/// Limits on a subdivision request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// The most faces any level may have.
    pub max_faces: u64,
}

impl Limits {
    /// The default face limit: 50 million (a few GB of half-edge mesh).
    pub const DEFAULT_MAX_FACES: u64 = 50_000_000;
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_faces: Self::DEFAULT_MAX_FACES,
        }
    }
}

/// Catmull-Clark subdivision, `levels` times (default [`Limits`]); see [the
/// rules](mod@catmull_clark).
///
/// # Errors
/// [`SubdivisionError::TooLarge`] above the default face limit.
pub fn catmull_clark(mesh: &HalfEdgeMesh, levels: u32) -> Result<HalfEdgeMesh, SubdivisionError> {
    subdivide(mesh, Scheme::CatmullClark, levels, &Limits::default())
}

/// Loop subdivision, `levels` times (default [`Limits`]); see [the rules](loop_scheme).
///
/// # Errors
/// [`SubdivisionError::NotTriangles`] for a mesh with a face that is not a triangle;
/// [`SubdivisionError::TooLarge`] above the default face limit.
pub fn loop_subdivision(
    mesh: &HalfEdgeMesh,
    levels: u32,
) -> Result<HalfEdgeMesh, SubdivisionError> {
    subdivide(mesh, Scheme::Loop, levels, &Limits::default())
}

/// Modified butterfly subdivision, `levels` times (default [`Limits`]); the old vertices keep
/// their positions bit for bit. See [the rules](mod@butterfly).
///
/// # Errors
/// As [`loop_subdivision`].
pub fn butterfly(mesh: &HalfEdgeMesh, levels: u32) -> Result<HalfEdgeMesh, SubdivisionError> {
    subdivide(mesh, Scheme::Butterfly, levels, &Limits::default())
}

/// Doo-Sabin subdivision, `levels` times (default [`Limits`]); see [the rules](mod@doo_sabin).
///
/// # Errors
/// [`SubdivisionError::TooLarge`] above the default face limit.
pub fn doo_sabin(mesh: &HalfEdgeMesh, levels: u32) -> Result<HalfEdgeMesh, SubdivisionError> {
    subdivide(mesh, Scheme::DooSabin, levels, &Limits::default())
}

/// [`SubdivisionError::NotTriangles`] for the first face that is not a triangle when `scheme`
/// needs them ([`Scheme::needs_triangles`]).
pub(crate) fn check_faces(mesh: &HalfEdgeMesh, scheme: Scheme) -> Result<(), SubdivisionError> {
    if scheme.needs_triangles()
        && let Some(f) = mesh
            .face_ids()
            .find(|&f| mesh.face_half_edges(f).count() != 3)
    {
        return Err(SubdivisionError::NotTriangles {
            scheme,
            face: f.index(),
            corners: mesh.face_half_edges(f).count(),
        });
    }
    Ok(())
}

/// `mesh` subdivided `levels` times by `scheme` (zero levels, or a mesh without faces: a copy).
///
/// # Errors
/// [`SubdivisionError::NotTriangles`] when Loop or butterfly get a face that is not a triangle;
/// [`SubdivisionError::TooLarge`] when a level would have more than `limits.max_faces` faces
/// (checked before any work); [`SubdivisionError::Rebuild`] if a level's faces do not form a
/// half-edge mesh (not expected: it would be a bug, reported rather than a panic).
pub fn subdivide(
    mesh: &HalfEdgeMesh,
    scheme: Scheme,
    levels: u32,
    limits: &Limits,
) -> Result<HalfEdgeMesh, SubdivisionError> {
    check_faces(mesh, scheme)?;
    if mesh.face_count() == 0 {
        return Ok(mesh.clone());
    }
    check_size(mesh, scheme, levels, limits)?;
    let step = match scheme {
        Scheme::CatmullClark => catmull_clark::step,
        Scheme::Loop => loop_scheme::step,
        Scheme::Butterfly => butterfly::step,
        Scheme::DooSabin => doo_sabin::step,
    };
    let mut current = mesh.clone();
    for _ in 0..levels {
        current = step(&current)?;
    }
    Ok(current)
}

/// Element counts of a mesh, for predicting the size of the next levels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    /// Vertices (isolated ones included).
    pub vertices: u64,
    /// Undirected edges.
    pub edges: u64,
    /// Faces.
    pub faces: u64,
    /// Face corners: the sum of the face degrees.
    pub corners: u64,
}

impl Counts {
    /// The counts of `mesh`.
    pub fn of(mesh: &HalfEdgeMesh) -> Counts {
        let boundary = mesh
            .half_edges()
            .iter()
            .filter(|h| h.face.is_none())
            .count();
        Counts {
            vertices: mesh.vertex_count() as u64,
            edges: mesh.edge_count() as u64,
            faces: mesh.face_count() as u64,
            corners: (mesh.half_edge_count() - boundary) as u64,
        }
    }

    /// The counts after one level of `scheme`: exact for Catmull-Clark, Loop and butterfly (any
    /// mesh), exact for Doo-Sabin on meshes (closed or open) without isolated or interior
    /// valence-2 vertices and an upper bound otherwise. Saturates instead of overflowing.
    pub fn next(self, scheme: Scheme) -> Counts {
        let Counts {
            vertices: v,
            edges: e,
            faces: f,
            corners: c,
        } = self;
        let sum = |a: u64, b: u64| a.saturating_add(b);
        let times = |k: u64, a: u64| a.saturating_mul(k);
        match scheme {
            Scheme::CatmullClark => Counts {
                vertices: sum(sum(v, e), f),
                edges: sum(times(2, e), c),
                faces: c,
                corners: times(4, c),
            },
            Scheme::Loop | Scheme::Butterfly => Counts {
                vertices: sum(v, e),
                edges: sum(times(2, e), times(3, f)),
                faces: times(4, f),
                corners: times(12, f),
            },
            // One vertex per corner and two per boundary edge (`E_b = 2E − c`); face loops of
            // F-faces (c corners), E-faces (4 each) and V-faces (Σ valence = 2E, plus one corner
            // per boundary vertex, as many as boundary edges): 8E corners, `E' = c + 2E + 2E_b`.
            Scheme::DooSabin => {
                let boundary = times(2, e).saturating_sub(c);
                Counts {
                    vertices: sum(c, times(2, boundary)),
                    edges: sum(sum(c, times(2, e)), times(2, boundary)),
                    faces: sum(sum(f, e), v),
                    corners: times(8, e),
                }
            }
        }
    }
}

/// Fails when some level would have more than `limits.max_faces` faces.
fn check_size(
    mesh: &HalfEdgeMesh,
    scheme: Scheme,
    levels: u32,
    limits: &Limits,
) -> Result<(), SubdivisionError> {
    let mut counts = Counts::of(mesh);
    for level in 1..=levels {
        counts = counts.next(scheme);
        if counts.faces > limits.max_faces {
            return Err(SubdivisionError::TooLarge {
                scheme,
                levels,
                level,
                faces: counts.faces,
                limit: limits.max_faces,
            });
        }
    }
    Ok(())
}
