//! A part with no polyhedral form (a true sphere, a blend, a wedge extruded to a segment) as a
//! polyhedron all the same: meshed by marching cubes on a grid of its own box, whose mesh is a
//! closed 2-manifold and so enters the mesh Booleans like any other. Only that part carries the
//! grid's error; every face of the polyhedral parts around it stays exact.

use super::{Polyhedral, PolyhedralError};
use crate::marching_cubes::GridSpec;
use crate::octree::{SparseOptions, mesh_sparse};
use solidkit_kernel::Solid;

impl Polyhedral {
    /// `solid` meshed by marching cubes with `resolution` cells along the longest side of its
    /// own bounding box (empty for a solid whose box has no volume); an error for an unbounded
    /// solid or a grid that cannot be built.
    pub fn gridded(solid: &Solid, resolution: usize) -> Result<Polyhedral, PolyhedralError> {
        let failed = |what: String| PolyhedralError::Failed(what);
        solid.validate().map_err(|e| failed(e.to_string()))?;
        let bounds = solid.bbox();
        if bounds.is_empty() || (bounds.max - bounds.min).min_element() <= 0.0 {
            return Ok(Polyhedral::empty());
        }
        if !(bounds.max - bounds.min).is_finite() {
            return Err(failed(
                "an unbounded part cannot be meshed on its own grid".into(),
            ));
        }
        let spec = GridSpec::for_bounds(&bounds, resolution).map_err(|e| failed(e.to_string()))?;
        let (mesh, _) = mesh_sparse(&solid.compile(), spec, &SparseOptions::default())
            .map_err(|e| failed(e.to_string()))?;
        if mesh.triangles.is_empty() {
            return Ok(Polyhedral::empty());
        }
        Polyhedral::from_mesh(&mesh)
    }
}
