//! 2D geometry under an extrusion, kept as a postfix program of leaves and Boolean operations
//! (no recursion to build, transform, drop or evaluate). Extrusions commute with 2D Booleans
//! (each slice is a bijective image of the profile), so `extrude(A − B) = extrude(A) − extrude(B)`:
//! every leaf becomes one kernel profile and the Booleans are replayed in 3D.

use super::facets;
use super::facets::Resolution;
use glam::DVec2;
use solidkit_kernel::profile::{Circle, Profile, ProfileError};

/// A 2D leaf.
#[derive(Debug, Clone, PartialEq)]
pub enum Leaf2 {
    /// A disc, with the resolution its faceted version uses.
    Circle {
        /// Centre.
        center: DVec2,
        /// Radius.
        radius: f64,
        /// `$fn/$fa/$fs` at the `circle` statement.
        res: Resolution,
    },
    /// Closed loops, inside by the even-odd rule.
    Polygon(Vec<Vec<DVec2>>),
}

/// One instruction of a [`Flat`] program.
#[derive(Debug, Clone, PartialEq)]
pub enum Op2 {
    /// Push a leaf.
    Leaf(Leaf2),
    /// Pop `n` and push their union.
    Union(usize),
    /// Pop `n` and push the first minus the others.
    Difference(usize),
    /// Pop `n` and push their intersection.
    Intersection(usize),
}

/// 2D geometry in postfix form; evaluates to exactly one region.
#[derive(Debug, Clone, PartialEq)]
pub struct Flat(pub Vec<Op2>);

impl Flat {
    /// One leaf.
    pub fn leaf(leaf: Leaf2) -> Flat {
        Flat(vec![Op2::Leaf(leaf)])
    }

    /// Combines parts with `op(n)` (a single part is returned as is).
    pub fn combine(parts: Vec<Flat>, op: fn(usize) -> Op2) -> Flat {
        let n = parts.len();
        let mut ops: Vec<Op2> = parts.into_iter().flat_map(|f| f.0).collect();
        if n > 1 {
            ops.push(op(n));
        }
        Flat(ops)
    }

    /// Applies the 2D affine map `p ↦ m·p + t` (rows `[a, b, tx]`, `[c, d, ty]`).
    pub fn transform(&mut self, m: [[f64; 3]; 2]) {
        let map = |p: DVec2| {
            DVec2::new(
                m[0][0] * p.x + m[0][1] * p.y + m[0][2],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2],
            )
        };
        let (c0, c1) = (DVec2::new(m[0][0], m[1][0]), DVec2::new(m[0][1], m[1][1]));
        let similarity = (c0.length() - c1.length()).abs() <= 1e-12 * c0.length().max(1.0)
            && c0.dot(c1).abs() <= 1e-12 * c0.length_squared().max(1.0);
        for op in &mut self.0 {
            let Op2::Leaf(leaf) = op else { continue };
            match leaf {
                Leaf2::Circle { center, radius, .. } if similarity => {
                    *center = map(*center);
                    *radius *= c0.length();
                }
                Leaf2::Circle {
                    center,
                    radius,
                    res,
                } => {
                    let n = facets::fragments(*radius, *res);
                    let pts = facets::circle(*radius, n)
                        .into_iter()
                        .map(|p| map(p + *center))
                        .collect();
                    *leaf = Leaf2::Polygon(vec![pts]);
                }
                Leaf2::Polygon(loops) => {
                    for l in loops {
                        for p in l.iter_mut() {
                            *p = map(*p);
                        }
                    }
                }
            }
        }
    }

    /// The number of leaves.
    pub fn leaf_count(&self) -> usize {
        self.0
            .iter()
            .filter(|op| matches!(op, Op2::Leaf(_)))
            .count()
    }

    /// Evaluates the program, turning each leaf into a value with `leaf` and combining values with
    /// `union`, `difference` and `intersection` (each given the popped values in order).
    pub fn evaluate<T, E>(
        &self,
        mut leaf: impl FnMut(&Leaf2) -> Result<T, E>,
        mut boolean: impl FnMut(&Op2, Vec<T>) -> T,
    ) -> Result<T, E> {
        let mut stack: Vec<T> = Vec::new();
        for op in &self.0 {
            match op {
                Op2::Leaf(l) => stack.push(leaf(l)?),
                Op2::Union(n) | Op2::Difference(n) | Op2::Intersection(n) => {
                    let parts = stack.split_off(stack.len() - n);
                    stack.push(boolean(op, parts));
                }
            }
        }
        Ok(stack.pop().expect("a flat program has one result"))
    }
}

/// The kernel profile of a leaf: an exact disc, or OpenSCAD's n-gon when `faceted`; polygons
/// take their largest loop as the outline and the others as holes.
pub fn profile(leaf: &Leaf2, faceted: bool) -> Result<Profile, ProfileError> {
    match leaf {
        Leaf2::Circle {
            center,
            radius,
            res,
        } if faceted => {
            let n = facets::fragments(*radius, *res);
            let pts = facets::circle(*radius, n)
                .into_iter()
                .map(|p| p + *center)
                .collect();
            Profile::polygon(pts, Vec::new())
        }
        Leaf2::Circle { center, radius, .. } => Profile::Circle(Circle {
            center: *center,
            radius: *radius,
        })
        .checked(),
        Leaf2::Polygon(loops) => {
            let mut loops = loops.clone();
            let outer = (0..loops.len())
                .max_by(|&a, &b| area(&loops[a]).abs().total_cmp(&area(&loops[b]).abs()))
                .unwrap_or(0);
            let outline = loops.swap_remove(outer);
            Profile::polygon(outline, loops)
        }
    }
}

/// Signed area of a loop (shoelace).
fn area(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum::<f64>()
        / 2.0
}
