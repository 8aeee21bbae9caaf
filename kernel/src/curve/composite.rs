//! Composite curves: a chain of curves (any kind but composite) joined end to start, each piece
//! mapped linearly onto the parameters `[i, i + 1]`, with a declared continuity at every joint
//! that is checked when the curve is built:
//!
//! - **C⁰**: the piece starts where the previous one ends (gap ≤ 1e-9 of the curve's size);
//! - **G¹**: C⁰ and the unit tangents agree (angle ≤ 1e-6 rad);
//! - **C¹**: C⁰ and the derivatives with respect to the composite parameter agree
//!   (difference ≤ 1e-9 of their size).
//!
//! A joint that does not hold is an error naming the piece and the measured gap or angle.

use super::bezier::points_bbox;
use super::piece::{BezierPiece, Jet};
use super::{Curve, Curve3, CurveError};
use crate::Aabb;

/// How two consecutive pieces join.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Continuity {
    /// Positions agree.
    C0,
    /// Positions and tangent directions agree.
    G1,
    /// Positions and first derivatives agree.
    C1,
}

impl Continuity {
    /// From the JSON spelling `"C0"`, `"G1"` or `"C1"` (case-insensitive).
    pub fn parse(s: &str) -> Option<Continuity> {
        match s.to_ascii_uppercase().as_str() {
            "C0" => Some(Continuity::C0),
            "G1" => Some(Continuity::G1),
            "C1" => Some(Continuity::C1),
            _ => None,
        }
    }

    /// The JSON spelling.
    pub fn name(self) -> &'static str {
        match self {
            Continuity::C0 => "C0",
            Continuity::G1 => "G1",
            Continuity::C1 => "C1",
        }
    }
}

/// A chain of curves on `[0, pieces]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Composite {
    parts: Vec<Curve>,
    joins: Vec<Continuity>,
}

/// The jet of `part` at its local parameter `s ∈ [0, 1]`, derivatives with respect to `s`.
fn local_jet(part: &Curve, s: f64) -> Jet {
    let (a, b) = part.domain();
    part.jet(a + s * (b - a)).rescaled(b - a)
}

impl Composite {
    /// The chain of `parts` (at least one, none composite) with `joins[i]` the continuity between
    /// parts `i` and `i + 1` (one fewer than the parts), checked.
    pub fn new(parts: Vec<Curve>, joins: Vec<Continuity>) -> Result<Composite, CurveError> {
        super::error::enough_points("pieces", parts.len(), 1)?;
        if let Some(index) = parts.iter().position(|p| matches!(p, Curve::Composite(_))) {
            return Err(CurveError::NestedComposite { index });
        }
        if joins.len() + 1 != parts.len() {
            return Err(CurveError::Join {
                index: 0,
                problem: format!(
                    "expected {} continuities (one per joint), found {}",
                    parts.len() - 1,
                    joins.len()
                ),
            });
        }
        let size = parts
            .iter()
            .map(|p| p.control_bbox().size().length())
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        for (i, join) in joins.iter().enumerate() {
            let end = local_jet(&parts[i], 1.0);
            let start = local_jet(&parts[i + 1], 0.0);
            let gap = (end.point - start.point).length();
            let fail = |problem: String| {
                Err(CurveError::Join {
                    index: i + 1,
                    problem,
                })
            };
            if gap > 1e-9 * size {
                return fail(format!(
                    "declared {} but it starts {gap:.3e} away from the end of pieces[{i}]",
                    join.name()
                ));
            }
            match join {
                Continuity::C0 => {}
                Continuity::G1 => {
                    let angle = end.d1.angle_between(start.d1);
                    if end.d1.length() == 0.0
                        || start.d1.length() == 0.0
                        || angle.is_nan()
                        || angle > 1e-6
                    {
                        return fail(format!(
                            "declared G1 but the tangents differ by {:.3e} degrees",
                            angle.to_degrees()
                        ));
                    }
                }
                Continuity::C1 => {
                    let scale = end
                        .d1
                        .length()
                        .max(start.d1.length())
                        .max(f64::MIN_POSITIVE);
                    let jump = (end.d1 - start.d1).length();
                    if jump > 1e-9 * scale {
                        return fail(format!(
                            "declared C1 but the derivative jumps from {:?} to {:?} (by {jump:.3e})",
                            end.d1.to_array(),
                            start.d1.to_array()
                        ));
                    }
                }
            }
        }
        Ok(Composite { parts, joins })
    }

    /// The pieces in order.
    pub fn parts(&self) -> &[Curve] {
        &self.parts
    }

    /// The declared continuity at each joint.
    pub fn joins(&self) -> &[Continuity] {
        &self.joins
    }

    /// The piece holding the composite parameter `t` and the local parameter `s ∈ [0, 1]`.
    fn locate(&self, t: f64) -> (usize, f64) {
        let n = self.parts.len();
        let t = t.clamp(0.0, n as f64);
        let i = (t.floor() as usize).min(n - 1);
        (i, t - i as f64)
    }
}

impl Curve3 for Composite {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.parts.len() as f64)
    }
    fn jet(&self, t: f64) -> Jet {
        let (i, s) = self.locate(t);
        local_jet(&self.parts[i], s)
    }
    fn control_bbox(&self) -> Aabb {
        let corners: Vec<_> = self
            .parts
            .iter()
            .flat_map(|p| {
                let b = p.control_bbox();
                [b.min, b.max]
            })
            .collect();
        points_bbox(&corners)
    }
    fn pieces(&self) -> Vec<BezierPiece> {
        let mut out = Vec::new();
        for (i, part) in self.parts.iter().enumerate() {
            let (a, b) = part.domain();
            let k = 1.0 / (b - a);
            for mut piece in part.pieces() {
                piece.t0 = i as f64 + (piece.t0 - a) * k;
                piece.t1 = i as f64 + (piece.t1 - a) * k;
                out.push(piece);
            }
        }
        out
    }
}
