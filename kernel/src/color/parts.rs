//! The coloured parts of a tree: the leaves of its Boolean/transform/colour skeleton, each in
//! world coordinates with the colour of its innermost `color` ancestor.

use super::Rgba;
use crate::solid::{NodeKind, Solid};
use crate::transform::Transform;
use std::sync::Arc;

/// One part of a tree for colouring a mesh: a primitive, or a whole offset, shell or smooth
/// Boolean (their surfaces are not any one leaf's), under all its ancestors' transforms.
#[derive(Debug, Clone)]
pub struct ColoredPart {
    /// The part in world coordinates (its transforms above it applied).
    pub solid: Solid,
    /// The colour of its innermost `color` ancestor, if any.
    pub color: Option<Rgba>,
}

/// A transform on the path from the root, linked to the one above it.
struct Link {
    transform: Transform,
    parent: Option<Arc<Link>>,
}

/// A node to visit, the transforms above it and its innermost colour.
type Frame<'a> = (&'a Solid, Option<Arc<Link>>, Option<Rgba>);

impl Solid {
    /// True when some node of the tree is a `color` node.
    pub fn has_color(&self) -> bool {
        let mut stack: Vec<&Solid> = vec![self];
        while let Some(s) = stack.pop() {
            if matches!(s.kind(), NodeKind::Color(_)) {
                return true;
            }
            stack.extend(s.children());
        }
        false
    }

    /// The parts of the tree with their colours, or `None` when the tree has no `color` node.
    ///
    /// The walk (explicit work list) descends through unions, intersections, differences,
    /// transforms and colours; every other node is one part. Inside a part (an offset, shell or
    /// smooth Boolean) `color` nodes are not looked at: the part takes its own innermost colour
    /// ancestor's colour. A shared subtree gives one part per use.
    pub fn colored_parts(&self) -> Option<Vec<ColoredPart>> {
        if !self.has_color() {
            return None;
        }
        let mut parts = Vec::new();
        let mut stack: Vec<Frame<'_>> = vec![(self, None, None)];
        while let Some((s, chain, color)) = stack.pop() {
            match s.kind() {
                NodeKind::Union | NodeKind::Intersection | NodeKind::Difference => {
                    for c in s.children().iter().rev() {
                        stack.push((c, chain.clone(), color));
                    }
                }
                NodeKind::Color(c) => {
                    for child in s.children() {
                        stack.push((child, chain.clone(), Some(*c)));
                    }
                }
                NodeKind::Transform(t) => {
                    let link = Arc::new(Link {
                        transform: **t,
                        parent: chain,
                    });
                    for child in s.children() {
                        stack.push((child, Some(link.clone()), color));
                    }
                }
                _ => {
                    let mut solid = s.clone();
                    let mut at = chain.as_deref();
                    while let Some(link) = at {
                        solid = Solid::from_parts(
                            NodeKind::Transform(Box::new(link.transform)),
                            vec![solid],
                        );
                        at = link.parent.as_deref();
                    }
                    parts.push(ColoredPart { solid, color });
                }
            }
        }
        Some(parts)
    }
}
