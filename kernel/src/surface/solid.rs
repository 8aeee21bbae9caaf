//! A surface node as a CSG operand: its closed tessellation as a [`MeshSolid`] that keeps the
//! node's description (so the JSON writer writes the node back as it was read).

use super::close::close;
use super::error::SurfaceError;
use super::sample::{Sampled, sample};
use super::spec::SurfaceSpec;
use crate::IndexedMesh;
use crate::primitive::{MeshResolver, MeshSolid, MeshSource};

impl SurfaceSpec {
    /// The open (or closed) sheet: the tessellated surface with its normals and chord error.
    pub fn sheet(&self, resolver: &dyn MeshResolver) -> Result<Sampled, SurfaceError> {
        sample(self, resolver)
    }

    /// The closed, outward-wound triangle mesh of the solid.
    pub fn closed_mesh(&self, resolver: &dyn MeshResolver) -> Result<IndexedMesh, SurfaceError> {
        close(&self.sheet(resolver)?, self.closure)
    }

    /// The solid: the exact signed distance to [`SurfaceSpec::closed_mesh`].
    pub fn solid(&self, resolver: &dyn MeshResolver) -> Result<MeshSolid, SurfaceError> {
        let mesh = self.closed_mesh(resolver)?;
        Ok(MeshSolid::with_source(
            MeshSource::Surface(Box::new(self.clone())),
            &mesh,
        )?)
    }
}
