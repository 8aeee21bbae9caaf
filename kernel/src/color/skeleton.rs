//! The Boolean skeleton of a coloured tree: its parts (the leaves of the
//! Boolean/transform/colour skeleton, each in world coordinates with its innermost colour) and
//! the min/max nodes that combine their fields into the tree's field, so a point can be traced
//! from the root to the part whose surface the tree's surface is there.
//!
//! Negations are pushed down to the parts (`a − b = max(a, −b)`, `−min(a, b) = max(−a, −b)`) and
//! nested nodes of the same operation are merged (`union(union(a, b), c)` is `min(a, b, c)`), so
//! every node is a plain minimum or maximum of its operands in tree order, and its value at a
//! point is exactly the tree's lowered field (transforms only scale a part's field by a positive
//! factor, which no minimum or maximum notices).

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

/// An operand of a [`SkeletonNode`], or the root of a [`ColorSkeleton`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Operand {
    /// Part `index` of [`ColorSkeleton::parts`]; its value is the part's field, negated when
    /// `negated` (a cutter, or a part under an odd number of cutter positions).
    Part {
        /// Index into [`ColorSkeleton::parts`].
        index: u32,
        /// Whether the part's field enters negated.
        negated: bool,
    },
    /// Node `index` of [`ColorSkeleton::nodes`].
    Node(u32),
}

/// A node of the skeleton: the minimum or maximum of its operands' values.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SkeletonNode {
    /// `true`: the maximum of the operands (an intersection, a difference, a negated union);
    /// `false`: the minimum (a union, a negated intersection or difference). With no operands
    /// the value is `+∞` for a minimum and `−∞` for a maximum.
    pub max: bool,
    /// The operands in tree order. A node operand always has a larger index than its parent.
    pub operands: Vec<Operand>,
}

/// A coloured tree's parts and the min/max skeleton over them (see the module docs).
#[derive(Debug, Clone)]
pub struct ColorSkeleton {
    /// The parts in tree order (depth first, children in order), as [`Solid::colored_parts`].
    pub parts: Vec<ColoredPart>,
    /// The nodes; an operand node's index is larger than its parent's, so visiting the nodes
    /// from the last to the first sees every operand before the node that uses it.
    pub nodes: Vec<SkeletonNode>,
    /// The root: a part (a tree that is one painted part) or node 0.
    pub root: Operand,
}

/// A transform on the path from the root, linked to the one above it.
struct Link {
    transform: Transform,
    parent: Option<Arc<Link>>,
}

/// A node to visit: the solid, the transforms above it, its innermost colour, the skeleton
/// node it is an operand of (`None`: the root) and whether its field enters negated.
struct Frame<'a> {
    solid: &'a Solid,
    chain: Option<Arc<Link>>,
    color: Option<Rgba>,
    parent: Option<u32>,
    negated: bool,
}

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

    /// The parts of the tree with their colours, or `None` when the tree has no `color` node
    /// (the parts of [`Solid::color_skeleton`]).
    ///
    /// The walk (explicit work list) descends through unions, intersections, differences,
    /// transforms and colours; every other node is one part. Inside a part (an offset, shell or
    /// smooth Boolean) `color` nodes are not looked at: the part takes its own innermost colour
    /// ancestor's colour. A shared subtree gives one part per use.
    pub fn colored_parts(&self) -> Option<Vec<ColoredPart>> {
        self.color_skeleton().map(|s| s.parts)
    }

    /// The parts of the tree and the min/max skeleton combining them (see
    /// [`ColorSkeleton`]), or `None` when the tree has no `color` node. One walk with an
    /// explicit work list, linear in the tree's size.
    pub fn color_skeleton(&self) -> Option<ColorSkeleton> {
        if !self.has_color() {
            return None;
        }
        let mut parts = Vec::new();
        let mut nodes: Vec<SkeletonNode> = Vec::new();
        let mut root = None;
        let mut stack = vec![Frame {
            solid: self,
            chain: None,
            color: None,
            parent: None,
            negated: false,
        }];
        while let Some(f) = stack.pop() {
            let s = f.solid;
            let children = s.children();
            let boolean = match s.kind() {
                // min of the operands, max when negated; no operand: the empty solid (+∞)
                NodeKind::Union => Some(f.negated),
                NodeKind::Difference if children.is_empty() => Some(f.negated),
                // max(a, −b, …) and max(a, b, …); min when negated
                NodeKind::Intersection | NodeKind::Difference => Some(!f.negated),
                _ => None,
            };
            if let Some(max) = boolean {
                // merged into the parent when it takes the same extremum
                let node = match f.parent {
                    Some(p) if nodes[p as usize].max == max => p,
                    _ => {
                        let id = nodes.len() as u32;
                        nodes.push(SkeletonNode {
                            max,
                            operands: Vec::new(),
                        });
                        attach(&mut nodes, &mut root, f.parent, Operand::Node(id));
                        id
                    }
                };
                let cutters = matches!(s.kind(), NodeKind::Difference);
                for (k, c) in children.iter().enumerate().rev() {
                    stack.push(Frame {
                        solid: c,
                        chain: f.chain.clone(),
                        color: f.color,
                        parent: Some(node),
                        negated: f.negated ^ (cutters && k > 0),
                    });
                }
                continue;
            }
            match s.kind() {
                NodeKind::Color(c) => {
                    for child in children.iter().rev() {
                        stack.push(Frame {
                            solid: child,
                            color: Some(*c),
                            chain: f.chain.clone(),
                            ..f
                        });
                    }
                }
                NodeKind::Transform(t) => {
                    let link = Arc::new(Link {
                        transform: **t,
                        parent: f.chain.clone(),
                    });
                    for child in children.iter().rev() {
                        stack.push(Frame {
                            solid: child,
                            chain: Some(link.clone()),
                            ..f
                        });
                    }
                }
                _ => {
                    let mut solid = s.clone();
                    let mut at = f.chain.as_deref();
                    while let Some(link) = at {
                        solid = Solid::from_parts(
                            NodeKind::Transform(Box::new(link.transform)),
                            vec![solid],
                        );
                        at = link.parent.as_deref();
                    }
                    let index = parts.len() as u32;
                    parts.push(ColoredPart {
                        solid,
                        color: f.color,
                    });
                    let part = Operand::Part {
                        index,
                        negated: f.negated,
                    };
                    attach(&mut nodes, &mut root, f.parent, part);
                }
            }
        }
        // a tree whose colour nodes hold nothing (an empty transform chain) has no part: the
        // empty solid, an empty minimum
        let root = root.unwrap_or_else(|| {
            nodes.push(SkeletonNode {
                max: false,
                operands: Vec::new(),
            });
            Operand::Node(0)
        });
        Some(ColorSkeleton { parts, nodes, root })
    }
}

/// Makes `operand` the next operand of `parent`, or the root.
fn attach(
    nodes: &mut [SkeletonNode],
    root: &mut Option<Operand>,
    parent: Option<u32>,
    operand: Operand,
) {
    match parent {
        Some(p) => nodes[p as usize].operands.push(operand),
        None => *root = Some(operand),
    }
}
