//! Adaptive subdivision (Loop and Catmull-Clark): each level refines only the faces that are not
//! yet flat to a tolerance, and closes the result so that it stays a crack-free manifold.
//!
//! One level:
//! 1. The next level's points are computed as for uniform subdivision (vertex, edge and, for
//!    Catmull-Clark, face points, with the same rules and boundary rules).
//! 2. A face is **flat** when every point the next level puts on it — the vertex points of its
//!    corners, the edge points of its edges, its face point — lies within `tolerance` of the
//!    face's plane (through its centroid, with the Newell normal). A face that is not flat is
//!    refined. So a flat region (whose points the rules keep in its plane) stays coarse, and a
//!    face whose next level would move off it by more than `tolerance` is split.
//! 3. Every old vertex moves to its vertex point (a vertex of a flat face moves by at most
//!    `tolerance` off that face), so all faces keep sharing their corners: no cracks.
//! 4. Closure, so that no face has a vertex in the middle of an edge that it does not use:
//!    - **Loop (red-green)**: refined faces are split 1-to-4 ("red"); a face with two or three
//!      split edges becomes red too (repeated until none is left, by a work list); a face with
//!      one split edge is bisected from that edge's point to the opposite corner ("green"); the
//!      rest stay.
//!    - **Catmull-Clark (refine, then conform)**: refined faces become their quads; a face that
//!      is not refined takes the edge points of its split edges as extra corners (a polygon with
//!      more corners, which Catmull-Clark accepts at the next level), so every edge is shared by
//!      exactly the faces that shared it.
//!
//! Edge and face points no face uses are dropped; old vertices keep their ids. Every level's
//! faces are rebuilt into a [`HalfEdgeMesh`], which checks that the result is manifold. Green
//! triangles are treated as ordinary triangles at the next level (no un-refinement), so a region
//! refined over several levels can carry thinner triangles along its border than uniform Loop.

use glam::DVec3;

use super::edges::EdgeIndex;
use super::{Counts, Limits, Scheme, SubdivisionError, catmull_clark, loop_scheme};
use crate::halfedge::{FaceId, HalfEdgeMesh};

/// What one adaptive level did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AdaptiveLevel {
    /// Faces before the level.
    pub faces_in: usize,
    /// Faces refined because they were not flat to the tolerance.
    pub refined: usize,
    /// Faces refined by the closure (Loop: two or more split edges).
    pub closure_refined: usize,
    /// Faces bisected (Loop, green) or given extra corners (Catmull-Clark) to stay conforming.
    pub conformed: usize,
    /// Faces left as they were.
    pub kept: usize,
    /// Faces after the level.
    pub faces_out: usize,
}

/// `mesh` subdivided adaptively by `scheme` (Loop or Catmull-Clark) for at most `levels` levels,
/// refining only faces that are not flat to `tolerance` (see the [module docs](self)); stops early
/// when a level refines nothing. Returns the mesh and one record per level run.
///
/// # Errors
/// [`SubdivisionError::NotAdaptive`] for butterfly and Doo-Sabin;
/// [`SubdivisionError::Tolerance`] unless `tolerance` is positive and finite;
/// [`SubdivisionError::NotTriangles`] for Loop on a mesh with other faces;
/// [`SubdivisionError::TooLarge`] when a level could exceed `limits.max_faces` (its uniform
/// count, checked before the level); [`SubdivisionError::Rebuild`] if a level's faces do not form
/// a half-edge mesh (a bug, reported rather than a panic).
pub fn subdivide_adaptive(
    mesh: &HalfEdgeMesh,
    scheme: Scheme,
    levels: u32,
    tolerance: f64,
    limits: &Limits,
) -> Result<(HalfEdgeMesh, Vec<AdaptiveLevel>), SubdivisionError> {
    if !matches!(scheme, Scheme::Loop | Scheme::CatmullClark) {
        return Err(SubdivisionError::NotAdaptive { scheme });
    }
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(SubdivisionError::Tolerance(tolerance.to_string()));
    }
    super::check_faces(mesh, scheme)?;
    let mut current = mesh.clone();
    let mut records = Vec::new();
    for level in 1..=levels {
        if current.face_count() == 0 {
            break;
        }
        let bound = Counts::of(&current).next(scheme).faces;
        if bound > limits.max_faces {
            return Err(SubdivisionError::TooLarge {
                scheme,
                levels,
                level,
                faces: bound,
                limit: limits.max_faces,
            });
        }
        let (next, record) = level_step(&current, scheme, tolerance)?;
        current = next;
        records.push(record);
        if record.refined == 0 {
            break;
        }
    }
    Ok((current, records))
}

/// One adaptive level.
fn level_step(
    mesh: &HalfEdgeMesh,
    scheme: Scheme,
    tolerance: f64,
) -> Result<(HalfEdgeMesh, AdaptiveLevel), SubdivisionError> {
    let edges = EdgeIndex::new(mesh);
    let loop_scheme = scheme == Scheme::Loop;
    let points = if loop_scheme {
        loop_scheme::points(mesh, &edges)
    } else {
        catmull_clark::points(mesh, &edges)
    };
    let edge_base = mesh.vertex_count() as u32;
    let face_base = edge_base + edges.count() as u32;
    let faces: Vec<FaceId> = mesh.face_ids().collect();
    let mut red: Vec<bool> = faces
        .iter()
        .map(|&f| {
            let face_point = (!loop_scheme).then(|| points[(face_base + f.0) as usize]);
            deviation(mesh, &edges, &points, f, edge_base, face_point) > tolerance
        })
        .collect();
    let refined = red.iter().filter(|&&r| r).count();
    let mut split = vec![false; edges.count()];
    for &f in faces.iter().filter(|f| red[f.index()]) {
        for h in mesh.face_half_edges(f) {
            split[edges.of(h) as usize] = true;
        }
    }
    let mut closure_refined = 0;
    if loop_scheme {
        closure_refined = close_red_green(mesh, &edges, &mut red, &mut split);
    }
    // Emit the faces.
    let mut out: Vec<Vec<u32>> = Vec::with_capacity(4 * faces.len());
    let mut conformed = 0;
    for &f in &faces {
        if red[f.index()] {
            if loop_scheme {
                let h0 = mesh.face_half_edge(f);
                let h1 = mesh.half_edge(h0).next;
                let h2 = mesh.half_edge(h1).next;
                let [a, b, c] = [h0, h1, h2].map(|h| mesh.half_edge(h).origin.0);
                let [ab, bc, ca] = [h0, h1, h2].map(|h| edge_base + edges.of(h));
                out.extend([
                    vec![a, ab, ca],
                    vec![b, bc, ab],
                    vec![c, ca, bc],
                    vec![ab, bc, ca],
                ]);
            } else {
                out.extend(
                    catmull_clark::face_quads(mesh, &edges, f, edge_base, face_base)
                        .map(|q| q.to_vec()),
                );
            }
            continue;
        }
        let ring: Vec<_> = mesh.face_half_edges(f).collect();
        let splits: Vec<usize> = (0..ring.len())
            .filter(|&k| split[edges.of(ring[k]) as usize])
            .collect();
        if splits.is_empty() {
            out.push(mesh.face_vertices(f).map(|v| v.0).collect());
            continue;
        }
        conformed += 1;
        if loop_scheme {
            // Exactly one split edge (the closure made the others red): bisect from its point.
            let k = splits[0];
            let a = mesh.half_edge(ring[k]).origin.0;
            let b = mesh.half_edge(ring[(k + 1) % 3]).origin.0;
            let c = mesh.half_edge(ring[(k + 2) % 3]).origin.0;
            let m = edge_base + edges.of(ring[k]);
            out.extend([vec![a, m, c], vec![m, b, c]]);
        } else {
            let mut polygon = Vec::with_capacity(2 * ring.len());
            for &h in &ring {
                polygon.push(mesh.half_edge(h).origin.0);
                if split[edges.of(h) as usize] {
                    polygon.push(edge_base + edges.of(h));
                }
            }
            out.push(polygon);
        }
    }
    let record = AdaptiveLevel {
        faces_in: faces.len(),
        refined,
        closure_refined,
        conformed,
        kept: faces.len() - refined - closure_refined - conformed,
        faces_out: out.len(),
    };
    // Keep the old vertices (ids stable), drop the edge and face points no face uses.
    let mut remap: Vec<u32> = (0..points.len() as u32).collect();
    let mut used = vec![false; points.len()];
    for face in &out {
        for &v in face {
            used[v as usize] = true;
        }
    }
    let mut positions = Vec::with_capacity(points.len());
    for (k, p) in points.iter().enumerate() {
        if k < edge_base as usize || used[k] {
            remap[k] = positions.len() as u32;
            positions.push(*p);
        }
    }
    for face in &mut out {
        for v in face.iter_mut() {
            *v = remap[*v as usize];
        }
    }
    Ok((HalfEdgeMesh::from_faces(positions, &out)?, record))
}

/// The largest distance from face `f`'s plane (through the centroid of its corners, Newell
/// normal) of the points the next level puts on it; the largest distance from the centroid when
/// the face has no normal.
fn deviation(
    mesh: &HalfEdgeMesh,
    edges: &EdgeIndex,
    points: &[DVec3],
    f: FaceId,
    edge_base: u32,
    face_point: Option<DVec3>,
) -> f64 {
    let p = mesh.positions();
    let corners: Vec<DVec3> = mesh.face_vertices(f).map(|v| p[v.index()]).collect();
    let centroid = corners.iter().sum::<DVec3>() / corners.len() as f64;
    let mut normal = DVec3::ZERO;
    for (k, a) in corners.iter().enumerate() {
        let b = corners[(k + 1) % corners.len()];
        normal += (*a - centroid).cross(b - centroid);
    }
    let normal = normal.normalize_or_zero();
    let distance = |q: DVec3| {
        if normal == DVec3::ZERO {
            (q - centroid).length()
        } else {
            (q - centroid).dot(normal).abs()
        }
    };
    let mut worst = face_point.map_or(0.0, distance);
    for h in mesh.face_half_edges(f) {
        let v = mesh.half_edge(h).origin;
        worst = f64::max(worst, distance(points[v.index()]));
        worst = f64::max(worst, distance(points[(edge_base + edges.of(h)) as usize]));
    }
    worst
}

/// Red-green closure of a triangle mesh: every face with two or more split edges becomes red
/// (its edges split), until none is left. Returns how many faces it made red.
fn close_red_green(
    mesh: &HalfEdgeMesh,
    edges: &EdgeIndex,
    red: &mut [bool],
    split: &mut [bool],
) -> usize {
    let mut work: Vec<FaceId> = mesh.face_ids().collect();
    let mut count = 0;
    while let Some(f) = work.pop() {
        if red[f.index()] {
            continue;
        }
        let n = mesh
            .face_half_edges(f)
            .filter(|&h| split[edges.of(h) as usize])
            .count();
        if n < 2 {
            continue;
        }
        red[f.index()] = true;
        count += 1;
        for h in mesh.face_half_edges(f) {
            let e = edges.of(h) as usize;
            if !split[e] {
                split[e] = true;
                if let Some(g) = mesh.half_edge(mesh.half_edge(h).twin).face {
                    work.push(g);
                }
            }
        }
    }
    count
}
