//! The mesh solid's tree: the kernel's [`TriangleBvh`] with one triangle per leaf, plus per node
//! the dipole data of fast winding numbers (Barill et al. 2018): the sum of its triangles' area
//! vectors, their area-weighted centroid and a radius around it containing all of them, filled
//! in children first over the BVH's flat nodes (children always come after their parent, so the
//! pass is a reverse loop).
//!
//! Repeated triangles (the same oriented triangle, corners bitwise equal up to rotation) are kept
//! once with a weight, their number of copies: the winding number counts each copy as before
//! (weight × solid angle, weight × area vector) and distances do not depend on copies, so the
//! field is that of the full mesh while a file of 40 000 coincident triangles costs one.

use crate::bvh::TriangleBvh;
use crate::polyhedra::PolyhedronError;
use crate::{Aabb, IndexedMesh};
use glam::DVec3;
use std::collections::HashMap;

/// A node's far-field data for winding numbers.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Dipole {
    /// Area-weighted centroid of the node's triangles.
    pub center: DVec3,
    /// Sum of the triangles' area vectors (half the cross product of two edges).
    pub area: DVec3,
    /// Radius around `center` containing every triangle of the node.
    pub radius: f64,
}

/// A mesh ready for queries: the BVH (triangles in slot order) and a dipole per node.
#[derive(Debug)]
pub(crate) struct MeshTree {
    pub bvh: TriangleBvh,
    /// Copies of each slot's triangle in the mesh (1 unless repeated).
    pub weights: Vec<f64>,
    /// Triangles of the mesh, copies included.
    pub count: usize,
    pub dipoles: Vec<Dipole>,
    pub bbox: Aabb,
    /// Distances up to this count as on the surface (rounding of the nearest-point computation).
    pub tolerance: f64,
}

impl MeshTree {
    /// Checks that the mesh can have a tree: at least one triangle and not too many, indices in
    /// range, finite coordinates.
    pub(crate) fn check(mesh: &IndexedMesh) -> Result<(), PolyhedronError> {
        if mesh.triangles.is_empty() {
            return Err(PolyhedronError::NoFaces);
        }
        let count = mesh.positions.len();
        for (face, t) in mesh.triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= count) {
                return Err(PolyhedronError::IndexOutOfRange { face, index, count });
            }
            if let Some(&vertex) = t.iter().find(|&&i| {
                let v = mesh.positions[i as usize];
                !v.is_finite() || v.abs().max_element() > crate::primitive::MAX_MAGNITUDE
            }) {
                let vertex = vertex as usize;
                return Err(PolyhedronError::NonFiniteVertex { vertex });
            }
        }
        if mesh.triangles.len() > TriangleBvh::MAX_TRIANGLES {
            let (count, max) = (mesh.triangles.len(), TriangleBvh::MAX_TRIANGLES);
            return Err(PolyhedronError::TooManyFaces { count, max });
        }
        Ok(())
    }

    /// The tree of a mesh that passed [`MeshTree::check`].
    pub(crate) fn new(mesh: &IndexedMesh) -> MeshTree {
        let (triangles, copies) =
            distinct((0..mesh.triangles.len()).map(|t| mesh.triangle_positions(t)));
        let bvh = TriangleBvh::new(triangles, 1).expect("checked: not too many triangles");
        let weights: Vec<f64> = (0..bvh.len())
            .map(|s| copies[bvh.slot_index(s) as usize])
            .collect();
        let bbox = bvh.bbox();
        let dipoles = dipoles(&bvh, &weights);
        MeshTree {
            bvh,
            weights,
            count: mesh.triangles.len(),
            dipoles,
            bbox,
            tolerance: 64.0 * f64::EPSILON * bbox.min.abs().max(bbox.max.abs()).max_element(),
        }
    }

    /// The corners of the triangles in slot order.
    pub(crate) fn triangles(&self) -> &[[DVec3; 3]] {
        self.bvh.corners()
    }
}

/// The distinct oriented triangles (first occurrences, in order) and the number of copies of
/// each.
fn distinct(triangles: impl Iterator<Item = [DVec3; 3]>) -> (Vec<[DVec3; 3]>, Vec<f64>) {
    let key = |t: &[DVec3; 3]| {
        let bits = t.map(|p| p.to_array().map(f64::to_bits));
        // The rotation starting at the smallest corner: equal for the same oriented triangle.
        let k = (0..3).min_by_key(|&k| bits[k]).unwrap_or(0);
        [bits[k], bits[(k + 1) % 3], bits[(k + 2) % 3]]
    };
    let mut index: HashMap<[[u64; 3]; 3], usize> = HashMap::new();
    let (mut out, mut copies) = (Vec::new(), Vec::new());
    for t in triangles {
        let next = out.len();
        let i = *index.entry(key(&t)).or_insert(next);
        if i == next {
            out.push(t);
            copies.push(1.0);
        } else {
            copies[i] += 1.0;
        }
    }
    (out, copies)
}

/// The dipole of every node, children before parents; slot `s` stands for `copies[s]` copies.
fn dipoles(bvh: &TriangleBvh, copies: &[f64]) -> Vec<Dipole> {
    let nodes = bvh.nodes();
    let n = nodes.len();
    let mut dipoles = vec![Dipole::default(); n];
    // Total unsigned area per node: the weights of the centroid.
    let mut weights = vec![0.0f64; n];
    for i in (0..n).rev() {
        let node = nodes[i];
        let (mut area, mut weighted, mut weight) = (DVec3::ZERO, DVec3::ZERO, 0.0);
        if node.is_leaf() {
            for s in node.slots() {
                let t = &bvh.corners()[s];
                let a = (t[1] - t[0]).cross(t[2] - t[0]) * 0.5 * copies[s];
                let w = a.length();
                area += a;
                weighted += (t[0] + t[1] + t[2]) / 3.0 * w;
                weight += w;
            }
        } else {
            let first = node.first as usize;
            for c in [first, first + 1] {
                area += dipoles[c].area;
                weighted += dipoles[c].center * weights[c];
                weight += weights[c];
            }
        }
        let (lo, hi) = (node.min, node.max);
        let center = if weight > 0.0 {
            (weighted / weight).clamp(lo, hi)
        } else {
            (lo + hi) * 0.5
        };
        let radius = (center - lo).max(hi - center).length();
        dipoles[i] = Dipole {
            center,
            area,
            radius,
        };
        weights[i] = weight;
    }
    dipoles
}
