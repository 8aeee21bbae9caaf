//! Reading the `dual` node: `{"type": "dual", "child": {polyhedral node}}`. The child is built
//! first (as any node); the node becomes a mesh primitive bounded by the dual of the child's
//! polygon mesh, which remembers its child for the writer.

use super::R;
use crate::primitive::{MeshSolid, MeshSolidError, Primitive};
use crate::solid::{NodeKind, Solid};

impl super::Params<'_, '_> {
    /// The dual of the node's one built child.
    pub(super) fn dual(&self, children: Vec<Solid>) -> R<Solid> {
        self.reject_unknown(&["child"])?;
        let child_at = self.at("child")?;
        let child = children
            .first()
            .ok_or_else(|| self.fail(child_at, "child", "missing child"))?;
        let NodeKind::Primitive(primitive) = child.kind() else {
            let e = MeshSolidError::NotDualizable {
                found: child.kind().name(),
            };
            return Err(self.fail(child_at, "child", e));
        };
        let mesh = MeshSolid::dual_of(primitive, self.reader.resolver).map_err(|e| match e {
            MeshSolidError::NotDualizable { .. } | MeshSolidError::Invalid(_) => {
                self.fail(child_at, "child", e)
            }
            _ => self.reader.located(self.index, &self.path(), e),
        })?;
        Ok(Solid::primitive(Primitive::Mesh(mesh)))
    }
}
