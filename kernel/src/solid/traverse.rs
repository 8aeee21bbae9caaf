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
        self.bbox_at(0.0)
    }

    /// A box containing `{p : f(p) ≤ level}` for the solid's field `f` and `level ≥ 0` (level 0:
    /// the solid). Offsets, shells and blends look at their operands' fields above zero, and
    /// fields that are only distance bounds (ellipsoids, Platonic solids, blobs) reach further
    /// there than their box grown by the level, so the level travels down the tree (issue 15:
    /// an offset ellipsoid left its box and was cut open by the grid). Explicit work list.
    pub fn bbox_at(&self, level: f64) -> Aabb {
        let mut frames: Vec<(&Solid, f64, usize)> = vec![(self, level.max(0.0), 0)];
        let mut results: Vec<Aabb> = Vec::new();
        while let Some(top) = frames.last_mut() {
            let (solid, level, next) = *top;
            if let Some(child) = solid.children().get(next) {
                top.2 += 1;
                frames.push((
                    child,
                    child_level(solid.kind(), solid.children().len(), level),
                    0,
                ));
            } else {
                frames.pop();
                let start = results.len() - solid.children().len();
                let b = match solid.kind() {
                    NodeKind::Primitive(p) => p.bbox_at(level),
                    NodeKind::SmoothUnion { .. } => results[start..]
                        .iter()
                        .fold(Aabb::empty(), |a, b| a.union(b)),
                    NodeKind::Offset { .. } | NodeKind::Shell { .. } | NodeKind::Color(_) => {
                        results.get(start).copied().unwrap_or(Aabb::empty())
                    }
                    kind => node_bbox(kind, &results[start..]),
                };
                results.truncate(start);
                results.push(b);
            }
        }
        results.pop().expect("the root leaves one result")
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
        NodeKind::Offset { .. } | NodeKind::Shell { .. } | NodeKind::Color(_) if n != 1 => {
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
        NodeKind::Color(c) => c.problem().map_or(Ok(()), Err),
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

/// The level at which a node of kind `kind` with `n` children, asked for `{f ≤ level}`, asks
/// its children: the node's field is at most `level` only where the children's are at most this.
fn child_level(kind: &NodeKind, n: usize, level: f64) -> f64 {
    match kind {
        // σ·f(A⁻¹(p − t)) ≤ ℓ ⇔ f ≤ ℓ/σ.
        NodeKind::Transform(t) => level / t.sigma,
        // Each quadratic smooth minimum lies at most r/4 below the plain minimum, and an n-ary
        // blend nests at most n − 1 of them; r covers up to five operands, as the boxes of
        // exact distance fields always did.
        NodeKind::SmoothUnion { radius } => level + radius * ((n.max(2) - 1) as f64 / 4.0).max(1.0),
        NodeKind::Offset { distance } => (level + distance).max(0.0),
        // |f| − t/2 ≤ ℓ ⇔ −(ℓ + t/2) ≤ f ≤ ℓ + t/2.
        NodeKind::Shell { thickness } => level + thickness * 0.5,
        // Minima, maxima and smooth maxima (never below the plain maximum) keep the level.
        _ => level,
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
        NodeKind::Color(_) => c.first().copied().unwrap_or(Aabb::empty()),
    }
}
