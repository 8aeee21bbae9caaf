//! A bounding volume hierarchy over the usable triangles of a mesh, for nearest-point queries and
//! the overlap queries of the self-intersection test: the kernel's
//! [`TriangleBvh`](solidkit_kernel::bvh::TriangleBvh) (obvhs build, exact `f64` node boxes, exact
//! nearest point) with up to four triangles per leaf, plus the mesh's triangle index of each slot
//! and the errors of meshes without a measurable surface.

use glam::DVec3;
use solidkit_kernel::bvh::{BvhError, TriangleBvh};

use super::MeasureError;
use crate::IndexedMesh;
use crate::usable::is_usable;

/// Most triangles per leaf.
const LEAF_SIZE: u32 = 4;

/// A triangle mesh ready for distance queries; see the [`crate::measure`] docs.
pub struct TriangleTree {
    /// The tree over the usable triangles.
    bvh: TriangleBvh,
    /// The index in the input mesh of the triangle in each slot.
    ids: Vec<u32>,
}

/// The point of a mesh nearest to a query.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nearest {
    /// Distance from the query to `point`.
    pub distance: f64,
    /// The nearest point of the mesh.
    pub point: DVec3,
    /// The triangle it lies on (index into the input mesh's triangles).
    pub triangle: u32,
}

impl TriangleTree {
    /// The tree of the usable triangles of `mesh` (three distinct in-range indices; see the
    /// topology report). Fails when there are none or a used vertex is not finite.
    pub fn new(mesh: &IndexedMesh) -> Result<Self, MeasureError> {
        let n = mesh.positions.len();
        let usable: Vec<u32> = (0..mesh.triangles.len())
            .filter(|&t| is_usable(&mesh.triangles[t], n))
            .map(|t| u32::try_from(t).map_err(|_| MeasureError::TooLarge { count: t + 1 }))
            .collect::<Result<_, _>>()?;
        if usable.is_empty() {
            return Err(MeasureError::NoSurface);
        }
        let corners: Vec<[DVec3; 3]> = usable
            .iter()
            .map(|&t| mesh.triangle_positions(t as usize))
            .collect();
        for (&t, c) in usable.iter().zip(&corners) {
            if let Some(k) = (0..3).find(|&k| !c[k].is_finite()) {
                let vertex = mesh.triangles[t as usize][k] as usize;
                return Err(MeasureError::NonFiniteVertex { vertex });
            }
        }
        let bvh = TriangleBvh::new(corners, LEAF_SIZE).map_err(|e| match e {
            BvhError::TooLarge { count } => MeasureError::TooLarge { count },
        })?;
        let ids = bvh.order().iter().map(|&i| usable[i as usize]).collect();
        Ok(Self { bvh, ids })
    }

    /// Number of triangles in the tree.
    pub fn triangle_count(&self) -> usize {
        self.bvh.len()
    }

    /// The exact bounding box `[min, max]` of the triangles.
    pub fn bbox(&self) -> [DVec3; 2] {
        let b = self.bvh.bbox();
        [b.min, b.max]
    }

    /// The point of the mesh nearest to `q`.
    pub fn nearest(&self, q: DVec3) -> Nearest {
        // A tree always has triangles (`new` refuses meshes without).
        self.bvh.nearest(q).map_or(
            Nearest {
                distance: f64::INFINITY,
                point: q,
                triangle: 0,
            },
            |near| Nearest {
                distance: near.distance2.sqrt(),
                point: near.point,
                triangle: self.ids[near.slot as usize],
            },
        )
    }

    /// The shared tree (slots are its order, `0..triangle_count()`).
    #[cfg(test)]
    pub(crate) fn bvh(&self) -> &TriangleBvh {
        &self.bvh
    }

    /// The corners of the triangle in `slot`.
    #[cfg(test)]
    pub(crate) fn slot_corners(&self, slot: usize) -> [DVec3; 3] {
        self.bvh.corners()[slot]
    }

    /// The index in the input mesh of the triangle in `slot`.
    #[cfg(test)]
    pub(crate) fn slot_triangle(&self, slot: usize) -> u32 {
        self.ids[slot]
    }
}

impl std::fmt::Debug for TriangleTree {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TriangleTree")
            .field("nodes", &self.bvh.nodes().len())
            .field("triangles", &self.bvh.len())
            .finish()
    }
}
