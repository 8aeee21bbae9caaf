//! The boundary of a union of grid cubes (voxels) as an exact, closed, outward-wound triangle
//! mesh: every face between a filled and an empty voxel (or the outside) becomes one square of two
//! triangles, and the squares' corners are lattice points shared by index, so faces between two
//! filled voxels vanish and the result is welded by construction.
//!
//! The surface is a 2-manifold exactly when no two filled voxels meet only along an edge or only
//! at a corner with the voxels between them empty; the Menger sponges have no such contacts (see
//! `models::menger_mesh`, with the `models` feature). Coplanar squares are not merged: a surface of
//! `S` squares has `2S` triangles and `3S` edges.

use crate::IndexedMesh;
use glam::DVec3;

/// A box of voxels of side `cell`, voxel `(0, 0, 0)` having its lowest corner at `origin`.
#[derive(Debug, Clone, PartialEq)]
pub struct VoxelGrid {
    dims: [usize; 3],
    origin: DVec3,
    cell: f64,
    filled: Vec<bool>,
}

/// A voxel grid that cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VoxelError {
    /// Too many lattice points for 32-bit vertex indices, or a zero dimension.
    #[error("voxel grid {dims:?} must be non-empty with at most 2^31 lattice points")]
    Size {
        /// The dimensions asked for.
        dims: [usize; 3],
    },
    /// The cell size or origin is not finite and positive.
    #[error("voxel cell size must be positive and finite, and the origin finite")]
    Cell,
}

impl VoxelGrid {
    /// A grid of `dims` voxels; `filled(x, y, z)` says which are solid.
    pub fn new(
        dims: [usize; 3],
        origin: DVec3,
        cell: f64,
        filled: impl Fn(usize, usize, usize) -> bool,
    ) -> Result<VoxelGrid, VoxelError> {
        let lattice = dims
            .iter()
            .try_fold(1usize, |n, &d| n.checked_mul(d.checked_add(1)?));
        if dims.contains(&0) || lattice.is_none_or(|n| n > 1 << 31) {
            return Err(VoxelError::Size { dims });
        }
        if !(cell.is_finite() && cell > 0.0 && origin.is_finite()) {
            return Err(VoxelError::Cell);
        }
        let [nx, ny, nz] = dims;
        let mut cells = Vec::with_capacity(nx * ny * nz);
        for z in 0..nz {
            for y in 0..ny {
                for x in 0..nx {
                    cells.push(filled(x, y, z));
                }
            }
        }
        Ok(VoxelGrid {
            dims,
            origin,
            cell,
            filled: cells,
        })
    }

    /// Voxels along x, y and z.
    pub fn dims(&self) -> [usize; 3] {
        self.dims
    }

    /// True for a filled voxel; false outside the grid.
    pub fn is_filled(&self, v: [i64; 3]) -> bool {
        let [nx, ny, nz] = self.dims.map(|d| d as i64);
        let [x, y, z] = v;
        if x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz {
            return false;
        }
        self.filled[((z * ny + y) * nx + x) as usize]
    }

    /// Number of filled voxels.
    pub fn filled_count(&self) -> usize {
        self.filled.iter().filter(|&&f| f).count()
    }

    /// The boundary squares as a triangle mesh (see the module docs). Voxels are visited z, y, x
    /// ascending, faces in the order −x, +x, −y, +y, −z, +z, and vertices are numbered in order of
    /// first use, so the mesh is the same on every run. Each square `c0 c1 c2 c3`
    /// (counter-clockwise from outside) is split along `c0 c2`.
    pub fn boundary(&self) -> IndexedMesh {
        let [nx, ny, nz] = self.dims;
        let (lx, ly) = (nx + 1, ny + 1);
        let mut ids = vec![u32::MAX; lx * ly * (nz + 1)];
        let mut mesh = IndexedMesh::default();
        let mut vertex = |p: [usize; 3], mesh: &mut IndexedMesh| -> u32 {
            let slot = &mut ids[(p[2] * ly + p[1]) * lx + p[0]];
            if *slot == u32::MAX {
                *slot = mesh.positions.len() as u32;
                let [x, y, z] = p.map(|c| c as f64 * self.cell);
                mesh.positions.push(self.origin + DVec3::new(x, y, z));
            }
            *slot
        };
        for z in 0..nz {
            for y in 0..ny {
                for x in 0..nx {
                    let v = [x, y, z];
                    if !self.is_filled(v.map(|c| c as i64)) {
                        continue;
                    }
                    for axis in 0..3 {
                        for positive in [false, true] {
                            let mut n = v.map(|c| c as i64);
                            n[axis] += if positive { 1 } else { -1 };
                            if self.is_filled(n) {
                                continue;
                            }
                            let corners = square(v, axis, positive);
                            let [a, b, c, d] = corners.map(|p| vertex(p, &mut mesh));
                            mesh.triangles.push([a, b, c]);
                            mesh.triangles.push([a, c, d]);
                        }
                    }
                }
            }
        }
        mesh
    }
}

/// The lattice corners of the face of voxel `v` across `axis` (on its `positive` side),
/// counter-clockwise seen from outside the voxel.
fn square(v: [usize; 3], axis: usize, positive: bool) -> [[usize; 3]; 4] {
    let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut base = v;
    if positive {
        base[axis] += 1;
    }
    let step = |p: [usize; 3], a: usize| {
        let mut q = p;
        q[a] += 1;
        q
    };
    let (c1, c3) = (step(base, u), step(base, w));
    let c2 = step(c1, w);
    // e_u × e_w = e_axis (cyclic order): outward on the positive side.
    if positive {
        [base, c1, c2, c3]
    } else {
        [base, c3, c2, c1]
    }
}
