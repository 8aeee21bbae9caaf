//! Whole-tree walks with explicit work lists: post-order folds, node counts, structural equality,
//! validation with the path of the offending node, and bounding boxes.

use super::{NodeKind, Solid};
use crate::primitive::Shape;
use crate::transform::Transform;
use crate::{Aabb, KernelError};

impl Solid {
    /// Folds the tree bottom-up without recursion: `f(node, results of its children)` is called
    /// once per node occurrence (shared subtrees are visited once per use), children before parents.
    pub fn fold<R>(&self, mut f: impl FnMut(&Solid, &[R]) -> R) -> R {
        let mut frames: Vec<(&Solid, usize)> = vec![(self, 0)];
        let mut results: Vec<R> = Vec::new();
        while let Some(top) = frames.last_mut() {
            let (solid, next) = *top;
            if let Some(child) = solid.children().get(next) {
                top.1 += 1;
                frames.push((child, 0));
            } else {
                frames.pop();
                let start = results.len() - solid.children().len();
                let r = f(solid, &results[start..]);
                results.truncate(start);
                results.push(r);
            }
        }
        results.pop().expect("the root leaves one result")
    }

    /// Number of nodes, counting a shared subtree once per use.
    pub fn node_count(&self) -> usize {
        self.fold(|_, children: &[usize]| 1 + children.iter().sum::<usize>())
    }

    /// Length of the longest root-to-leaf path (a leaf has depth 1).
    pub fn depth(&self) -> usize {
        self.fold(|_, children: &[usize]| 1 + children.iter().copied().max().unwrap_or(0))
    }

    /// A box containing the solid (infinite when the solid is unbounded, empty when it is empty).
    pub fn bbox(&self) -> Aabb {
        self.fold(|s, c: &[Aabb]| node_bbox(s.kind(), c))
    }

    /// Checks every node's parameters and arity. The error names the node by its path from the
    /// root in the JSON tree's terms (`children[2].child.radius`).
    pub fn validate(&self) -> Result<(), KernelError> {
        let mut frames: Vec<(&Solid, usize)> = vec![(self, 0)];
        while let Some(top) = frames.last_mut() {
            let (solid, next) = *top;
            if next == 0
                && let Err(problem) = check_node(solid)
            {
                return Err(KernelError::InvalidNode {
                    path: path_of(&frames),
                    problem,
                });
            }
            if let Some(child) = solid.children().get(next) {
                top.1 += 1;
                frames.push((child, 0));
            } else {
                frames.pop();
            }
        }
        Ok(())
    }
}

/// The problem with one node (parameters or number of children), if any.
fn check_node(solid: &Solid) -> Result<(), String> {
    let n = solid.children().len();
    let name = solid.kind().name();
    match solid.kind() {
        NodeKind::Primitive(p) => {
            if n != 0 {
                return Err(format!("{name} takes no children"));
            }
            p.validate().map_err(|e| e.to_string())
        }
        NodeKind::Transform(t) => {
            if n != 1 {
                return Err(format!("{name} takes exactly one child, found {n}"));
            }
            Transform::new(t.spec)
                .map(|_| ())
                .map_err(|e| e.to_string())
        }
        NodeKind::Difference | NodeKind::SmoothDifference { .. } if n == 0 => {
            Err(format!("{name} needs at least one child"))
        }
        NodeKind::Offset { .. } | NodeKind::Shell { .. } if n != 1 => {
            Err(format!("{name} takes exactly one child, found {n}"))
        }
        NodeKind::SmoothUnion { radius }
        | NodeKind::SmoothIntersection { radius }
        | NodeKind::SmoothDifference { radius }
            if !(radius.is_finite() && *radius > 0.0) =>
        {
            Err("radius: expected a positive number".into())
        }
        NodeKind::Offset { distance } if !distance.is_finite() => {
            Err("distance: expected a finite number".into())
        }
        NodeKind::Shell { thickness } if !(thickness.is_finite() && *thickness > 0.0) => {
            Err("thickness: expected a positive number".into())
        }
        _ => Ok(()),
    }
}

/// The path of the innermost frame, in JSON-tree terms, shortened in the middle when deep.
fn path_of(frames: &[(&Solid, usize)]) -> String {
    let mut parts: Vec<String> = Vec::new();
    for pair in frames.windows(2) {
        let (parent, visited) = pair[0];
        match parent.kind() {
            k if k.is_unary() => parts.push("child".into()),
            _ => parts.push(format!("children[{}]", visited - 1)),
        }
    }
    shorten_path(&parts)
}

/// Joins path segments with dots, eliding the middle of very deep paths.
pub(crate) fn shorten_path(parts: &[String]) -> String {
    const KEEP: usize = 4;
    if parts.is_empty() {
        return "root".into();
    }
    if parts.len() <= 2 * KEEP + 1 {
        return parts.join(".");
    }
    format!(
        "{}.(… {} levels …).{}",
        parts[..KEEP].join("."),
        parts.len() - 2 * KEEP,
        parts[parts.len() - KEEP..].join(".")
    )
}

impl PartialEq for Solid {
    /// Structural equality, compared with a work list (deep trees are safe).
    fn eq(&self, other: &Solid) -> bool {
        let mut pairs = vec![(self, other)];
        while let Some((a, b)) = pairs.pop() {
            if a.ptr_eq(b) {
                continue;
            }
            if a.kind() != b.kind() || a.children().len() != b.children().len() {
                return false;
            }
            pairs.extend(a.children().iter().zip(b.children()));
        }
        true
    }
}

/// The box of a node of kind `kind` whose children have boxes `c` (in the node's coordinates).
pub(crate) fn node_bbox(kind: &NodeKind, c: &[Aabb]) -> Aabb {
    match kind {
        NodeKind::Primitive(p) => p.bbox(),
        NodeKind::Union => c.iter().fold(Aabb::empty(), |a, b| a.union(b)),
        NodeKind::Intersection => c.iter().fold(Aabb::infinite(), |a, b| a.intersection(b)),
        NodeKind::Difference => c.first().copied().unwrap_or(Aabb::empty()),
        NodeKind::Transform(t) => c
            .first()
            .map_or(Aabb::empty(), |b| b.transformed(&t.forward)),
        // A smooth union adds material within r/4 of the children (for distance fields); r is
        // a generous margin.
        NodeKind::SmoothUnion { radius } => c
            .iter()
            .fold(Aabb::empty(), |a, b| a.union(b))
            .expanded(radius.max(0.0)),
        NodeKind::SmoothIntersection { .. } => {
            c.iter().fold(Aabb::infinite(), |a, b| a.intersection(b))
        }
        NodeKind::SmoothDifference { .. } => c.first().copied().unwrap_or(Aabb::empty()),
        NodeKind::Offset { distance } => c
            .first()
            .map_or(Aabb::empty(), |b| b.expanded(distance.max(0.0))),
        NodeKind::Shell { thickness } => c
            .first()
            .map_or(Aabb::empty(), |b| b.expanded(thickness.max(0.0) * 0.5)),
    }
}
