//! The solidkit side: the benchmark model compiled once, meshed by `mesh_sparse` (marching
//! cubes) or `mesh_dc` (dual contouring) on `GridSpec::covering(domain, n)`.

use solidkit_kernel::models::Model;
use solidkit_kernel::{IndexedMesh, Program};
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};

/// A model ready to mesh.
pub struct Case {
    program: Program,
    spec: GridSpec,
}

impl Case {
    /// The model `name` (`sphere`, `gyroid-sphere`) on an `n³` grid over its domain.
    pub fn new(name: &str, n: usize) -> Self {
        let model = Model::by_name(name).expect("benchmark model");
        Self {
            program: model.solid.compile(),
            spec: GridSpec::covering(&model.domain, n).expect("grid"),
        }
    }

    /// Meshes it (on the current rayon pool).
    pub fn mesh(&self) -> IndexedMesh {
        mesh_sparse(&self.program, self.spec, &SparseOptions::default())
            .expect("not cancelled")
            .0
    }

    /// Meshes it by dual contouring (on the current rayon pool).
    pub fn mesh_dc(&self) -> IndexedMesh {
        mesh_dc(&self.program, self.spec, &DcOptions::default())
            .expect("not cancelled")
            .0
    }
}
