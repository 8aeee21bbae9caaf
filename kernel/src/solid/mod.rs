//! The user-facing CSG tree: [`Solid`], a cheaply cloned handle to an immutable node.
//!
//! Every node stores its children in one `Vec`, so all whole-tree algorithms (drop, equality,
//! validation, bounding box, lowering, printing) walk the tree with explicit work lists and never
//! recurse: a left-leaning chain of 10⁵ unions is as safe as a flat one.

mod build;
mod traverse;

pub(crate) use traverse::node_bbox;
pub(crate) use traverse::shorten_path as shorten_path_pub;

use crate::primitive::Primitive;
use crate::transform::Transform;
use std::sync::Arc;

/// A solid: a handle to a node of a CSG tree. Cloning is an `Arc` clone.
#[derive(Clone)]
pub struct Solid(pub(crate) Arc<Node>);

/// One node of the tree: what it does and its children.
pub struct Node {
    /// The operation of this node.
    pub kind: NodeKind,
    /// Operands (empty for primitives, one for transforms, any number for Booleans).
    pub children: Vec<Solid>,
}

/// The operation a node performs on its children.
#[derive(Debug, Clone, PartialEq)]
pub enum NodeKind {
    /// A primitive solid (no children).
    Primitive(Primitive),
    /// Union of all children: `min` of their fields. No children: the empty solid.
    Union,
    /// Intersection of all children: `max` of their fields. No children: all of space.
    Intersection,
    /// The first child minus all the others: `max(f₀, −f₁, −f₂, …)`.
    Difference,
    /// The single child moved by an affine map (boxed: it is much larger than the other kinds).
    Transform(Box<Transform>),
    /// Union with fillets of radius `radius` where children meet (quadratic smooth minimum).
    SmoothUnion {
        /// Blend radius (field units).
        radius: f64,
    },
    /// Intersection with rounded creases of radius `radius` (quadratic smooth maximum).
    SmoothIntersection {
        /// Blend radius (field units).
        radius: f64,
    },
    /// The first child minus the others with rounded creases of radius `radius`.
    SmoothDifference {
        /// Blend radius (field units).
        radius: f64,
    },
    /// The single child grown by `distance` (shrunk when negative): `f − d`.
    Offset {
        /// Offset distance.
        distance: f64,
    },
    /// The single child hollowed to a wall of `thickness` centred on its surface: `|f| − t/2`.
    Shell {
        /// Wall thickness.
        thickness: f64,
    },
    /// The single child painted: the field is the child's, unchanged (the innermost colour wins;
    /// see [`Solid::colored_parts`]).
    Color(crate::color::Rgba),
}

impl NodeKind {
    /// The name of the operation in the JSON tree format.
    pub fn name(&self) -> &'static str {
        match self {
            NodeKind::Primitive(p) => p.name(),
            NodeKind::Union => "union",
            NodeKind::Intersection => "intersection",
            NodeKind::Difference => "difference",
            NodeKind::Transform(t) => match t.spec {
                crate::TransformSpec::Translate(_) => "translate",
                crate::TransformSpec::Rotate { .. } => "rotate",
                crate::TransformSpec::Scale(_) => "scale",
                crate::TransformSpec::Mirror(_) => "mirror",
                crate::TransformSpec::Affine(_) => "affine",
            },
            NodeKind::SmoothUnion { .. } => "smooth_union",
            NodeKind::SmoothIntersection { .. } => "smooth_intersection",
            NodeKind::SmoothDifference { .. } => "smooth_difference",
            NodeKind::Offset { .. } => "offset",
            NodeKind::Shell { .. } => "shell",
            NodeKind::Color(_) => "color",
        }
    }

    /// True for the kinds that take exactly one child (transforms, offset, shell, color).
    pub fn is_unary(&self) -> bool {
        matches!(
            self,
            NodeKind::Transform(_)
                | NodeKind::Offset { .. }
                | NodeKind::Shell { .. }
                | NodeKind::Color(_)
        )
    }
}

impl Solid {
    /// A node from its operation and children (no validation; see [`Solid::validate`]).
    pub fn from_parts(kind: NodeKind, children: Vec<Solid>) -> Solid {
        Solid(Arc::new(Node { kind, children }))
    }

    /// The operation at the root.
    pub fn kind(&self) -> &NodeKind {
        &self.0.kind
    }

    /// The root's operands.
    pub fn children(&self) -> &[Solid] {
        &self.0.children
    }

    /// True when both handles point at the same node (not a structural comparison).
    pub fn ptr_eq(&self, other: &Solid) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Drop for Node {
    /// Drops the subtree with a work list instead of recursion: children whose last handle is
    /// this node are unpacked onto the list, so the call stack stays flat for any depth.
    fn drop(&mut self) {
        let mut stack = std::mem::take(&mut self.children);
        while let Some(solid) = stack.pop() {
            if let Some(mut node) = Arc::into_inner(solid.0) {
                stack.append(&mut node.children);
            }
        }
    }
}

impl std::fmt::Debug for Solid {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Solid")
            .field("root", &self.kind().name())
            .field("children", &self.children().len())
            .field("nodes", &self.node_count())
            .finish()
    }
}

#[cfg(test)]
mod tests;
