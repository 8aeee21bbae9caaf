//! Reading the `subdivide` node: `{"type": "subdivide", "scheme": "loop", "levels": 2, "child":
//! {polyhedral node}}`, with an optional `"adaptive": TOL` (Loop and Catmull-Clark refine only
//! where the surface is not flat to `TOL`). The child is built first (as any node); the subdivision itself runs
//! through the reader's [`MeshResolver`](crate::primitive::MeshResolver) and the node becomes a
//! mesh primitive that remembers its scheme, levels and child.

use super::{Params, R, Value};
use crate::primitive::{MeshSolid, MeshSolidError, Primitive, SubdivisionScheme};
use crate::solid::{NodeKind, Solid};

impl Params<'_, '_> {
    /// The subdivided solid of the node's one built child.
    pub(super) fn subdivide(&self, children: Vec<Solid>) -> R<Solid> {
        let name = self.string("scheme")?;
        let scheme = SubdivisionScheme::from_name(name).ok_or_else(|| {
            let names: Vec<&str> = SubdivisionScheme::ALL.iter().map(|s| s.name()).collect();
            self.fail(
                self.at("scheme").unwrap_or(self.index),
                "scheme",
                format!(
                    "unknown scheme \"{name}\" (expected one of: {})",
                    names.join(", ")
                ),
            )
        })?;
        let levels = self.levels()?;
        let adaptive = match super::find(self.entries, "adaptive") {
            Some(_) => Some(self.positive("adaptive")?),
            None => None,
        };
        self.reject_unknown(&["scheme", "levels", "adaptive", "child"])?;
        let child_at = self.at("child")?;
        let child = children
            .first()
            .ok_or_else(|| self.fail(child_at, "child", "missing child"))?;
        let NodeKind::Primitive(primitive) = child.kind() else {
            let e = MeshSolidError::NotPolyhedral {
                found: child.kind().name(),
            };
            return Err(self.fail(child_at, "child", e));
        };
        let mesh = MeshSolid::subdivided(primitive, scheme, levels, adaptive, self.reader.resolver)
            .map_err(|e| match e {
                MeshSolidError::NotPolyhedral { .. } => self.fail(child_at, "child", e),
                _ => self.reader.located(self.index, &self.path(), e),
            })?;
        Ok(Solid::primitive(Primitive::Mesh(mesh)))
    }

    /// `levels`: a whole number from 0 to 2³² − 1.
    fn levels(&self) -> R<u32> {
        let at = self.at("levels")?;
        let x = match self.reader.doc.values[at as usize] {
            Value::Number(x) => x,
            ref v => {
                let found = v.type_name();
                return Err(self.fail(
                    at,
                    "levels",
                    format!("expected a whole number, found {found}"),
                ));
            }
        };
        if x >= 0.0 && x <= f64::from(u32::MAX) && x.fract() == 0.0 {
            Ok(x as u32)
        } else {
            Err(self.fail(
                at,
                "levels",
                format!("expected a whole number ≥ 0, found {x}"),
            ))
        }
    }
}
