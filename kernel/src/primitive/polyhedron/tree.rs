//! The bounding volume hierarchy of a triangle mesh, for distance and winding-number queries.
//!
//! `obvhs` builds the tree topology (PLOC over single-precision triangle boxes, taken in
//! coordinates normalised to the mesh's bounding box so that any finite mesh fits in `f32`);
//! the tree is then copied into a flat array of nodes with exact double-precision boxes, the
//! triangles reordered so each leaf owns a contiguous run, and every node given the dipole data
//! of fast winding numbers (Barill et al. 2018): the sum of its triangles' area vectors, their
//! area-weighted centroid and a radius around it containing all of them. Children always come
//! after their parent, so the bottom-up pass is a reverse loop, and the copy uses an explicit
//! stack.

use crate::polyhedra::PolyhedronError;
use crate::{Aabb, IndexedMesh};
use glam::{DVec3, Vec3, Vec3A};
use obvhs::aabb::Aabb as Box32;
use obvhs::{Boundable, BvhBuildParams};
use std::time::Duration;

/// One node: its exact box, and either two children (`count == 0`, children at `first` and
/// `first + 1`) or a leaf's triangles `first .. first + count`.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Node {
    pub min: DVec3,
    pub max: DVec3,
    pub first: u32,
    pub count: u32,
}

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

/// A mesh ready for queries: flat nodes (root first), dipoles per node and the triangles.
#[derive(Debug)]
pub(crate) struct MeshTree {
    pub nodes: Vec<Node>,
    pub dipoles: Vec<Dipole>,
    pub triangles: Vec<[DVec3; 3]>,
    pub bbox: Aabb,
    /// Distances up to this count as on the surface (rounding of the nearest-point computation).
    pub tolerance: f64,
}

/// A triangle's box for the builder.
struct TriangleBox(Box32);

impl Boundable for TriangleBox {
    fn aabb(&self) -> Box32 {
        self.0
    }
}

impl MeshTree {
    /// Checks that the mesh can have a tree: at least one triangle, indices in range, finite
    /// coordinates.
    pub(crate) fn check(mesh: &IndexedMesh) -> Result<(), PolyhedronError> {
        if mesh.triangles.is_empty() {
            return Err(PolyhedronError::NoFaces);
        }
        let count = mesh.positions.len();
        for (face, t) in mesh.triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= count) {
                return Err(PolyhedronError::IndexOutOfRange { face, index, count });
            }
            if let Some(&vertex) = t.iter().find(|&&i| !mesh.positions[i as usize].is_finite()) {
                let vertex = vertex as usize;
                return Err(PolyhedronError::NonFiniteVertex { vertex });
            }
        }
        Ok(())
    }

    /// The tree of a mesh that passed [`MeshTree::check`].
    pub(crate) fn new(mesh: &IndexedMesh) -> MeshTree {
        let triangles: Vec<[DVec3; 3]> = (0..mesh.triangles.len())
            .map(|t| mesh.triangle_positions(t))
            .collect();
        let bbox = triangles
            .iter()
            .flatten()
            .fold(Aabb::empty(), |b, p| b.union(&Aabb::new(*p, *p)));
        // Builder coordinates: the box mapped to about [-0.5, 0.5]³ (all zero if the extent
        // overflows, which only costs traversal speed).
        let extent = bbox.size().max_element();
        let center = bbox.min * 0.5 + bbox.max * 0.5;
        let scale = if extent.is_finite() && extent > 0.0 {
            1.0 / extent
        } else {
            0.0
        };
        let normalised = |p: DVec3| {
            let v = ((p - center) * scale).as_vec3();
            Vec3A::from(if v.is_finite() { v } else { Vec3::ZERO })
        };
        let boxes: Vec<TriangleBox> = triangles
            .iter()
            .map(|t| {
                let (lo, hi) = t.iter().fold(
                    (Vec3A::splat(f32::INFINITY), Vec3A::splat(f32::NEG_INFINITY)),
                    |(lo, hi), p| (lo.min(normalised(*p)), hi.max(normalised(*p))),
                );
                TriangleBox(Box32::new(lo - 1e-6, hi + 1e-6))
            })
            .collect();
        let params = BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::fast_build()
        };
        let bvh = obvhs::bvh2::builder::build_bvh2(&boxes, params, &mut Duration::default());
        let (nodes, order) = flatten(&bvh);
        let triangles: Vec<[DVec3; 3]> = order.iter().map(|&i| triangles[i as usize]).collect();
        let mut tree = MeshTree {
            nodes,
            dipoles: Vec::new(),
            triangles,
            bbox,
            tolerance: 64.0 * f64::EPSILON * bbox.min.abs().max(bbox.max.abs()).max_element(),
        };
        tree.refit();
        tree
    }

    /// Exact boxes and dipoles, children before parents (children have larger indices).
    fn refit(&mut self) {
        let n = self.nodes.len();
        let mut dipoles = vec![Dipole::default(); n];
        // Total unsigned area per node: the weights of the centroid.
        let mut weights = vec![0.0f64; n];
        for i in (0..n).rev() {
            let node = self.nodes[i];
            let (first, count) = (node.first as usize, node.count as usize);
            let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
            let (mut area, mut weighted, mut weight) = (DVec3::ZERO, DVec3::ZERO, 0.0);
            if count > 0 {
                for t in &self.triangles[first..first + count] {
                    for p in t {
                        lo = lo.min(*p);
                        hi = hi.max(*p);
                    }
                    let a = (t[1] - t[0]).cross(t[2] - t[0]) * 0.5;
                    let w = a.length();
                    area += a;
                    weighted += (t[0] + t[1] + t[2]) / 3.0 * w;
                    weight += w;
                }
            } else {
                for c in [first, first + 1] {
                    lo = lo.min(self.nodes[c].min);
                    hi = hi.max(self.nodes[c].max);
                    area += dipoles[c].area;
                    weighted += dipoles[c].center * weights[c];
                    weight += weights[c];
                }
            }
            let center = if weight > 0.0 {
                (weighted / weight).clamp(lo, hi)
            } else {
                (lo + hi) * 0.5
            };
            let radius = (center - lo).max(hi - center).length();
            self.nodes[i].min = lo;
            self.nodes[i].max = hi;
            dipoles[i] = Dipole {
                center,
                area,
                radius,
            };
            weights[i] = weight;
        }
        self.dipoles = dipoles;
    }
}

/// Copies the builder's tree into the flat layout: nodes in depth-first order of allocation (two
/// children side by side) and the original triangle index of each reordered triangle.
fn flatten(bvh: &obvhs::bvh2::Bvh2) -> (Vec<Node>, Vec<u32>) {
    let mut nodes = vec![Node::default()];
    let mut order = Vec::with_capacity(bvh.primitive_indices.len());
    let mut stack: Vec<(usize, usize)> = vec![(0, 0)];
    while let Some((src, dst)) = stack.pop() {
        let n = &bvh.nodes[src];
        if n.prim_count == 0 {
            let first = nodes.len();
            nodes.push(Node::default());
            nodes.push(Node::default());
            nodes[dst].first = first as u32;
            stack.push((n.first_index as usize, first));
            stack.push((n.first_index as usize + 1, first + 1));
        } else {
            nodes[dst].first = order.len() as u32;
            nodes[dst].count = n.prim_count;
            let run = n.first_index as usize..(n.first_index + n.prim_count) as usize;
            order.extend_from_slice(&bvh.primitive_indices[run]);
        }
    }
    (nodes, order)
}
