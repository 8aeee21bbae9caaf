//! The sign of the field at a point where it is zero, by symbolic perturbation.
//!
//! A sample that lands exactly on a surface has value 0 and no sign. Counting it as outside (or
//! inside) invents surfaces wherever two surfaces meet there: two boxes that share a face have
//! `min(f₁, f₂) = 0` on the whole shared face, so a plane of samples on it would be "outside" and
//! split the union in two; a cutter flush with a face has `max(f, −g) = 0` over the hole, so "zero
//! is inside" would leave a skin over the hole. What the solid means at such a point is the sign
//! of the field an infinitesimal step away, along a fixed generic direction [`PERTURBATION`]:
//! `sign f(p + ε·d)` for ε → 0⁺.
//!
//! [`Program::zero_side`] evaluates that limit through the program as a pair per value,
//! `(f(p), ∂f/∂d(p))`, compared lexicographically: `min`/`max` of two operands whose values tie
//! (within [`tie_tolerance`], the single-precision noise band the samplers snap to zero) keep the
//! one with the smaller (larger) directional derivative, which is what `min`/`max` of
//! `f(p) + ε·∂f/∂d` does. Each leaf's one-sided derivative is a forward difference over a step of
//! `1e-7` of the coordinate scale, exact in sign at creases and corners of polytopes (where a
//! gradient would pick one face) and giving the second-order sign where the first order vanishes.
//! The step rule decides only zeros where operands meet from opposite sides (a contact, below).
//! A zero on a surface no other operand touches is [`ZeroSide::Surface`]: the program leaves it
//! to the polygonizer, which knows the lattice (the step would make the vertex sample of a sharp
//! tip an inside island, and "always outside" bevels every face lying on a sample plane by a
//! cell). Otherwise the final sign is the value's when it lies outside the tie band, else the
//! derivative's; a derivative of exactly 0 counts as outside, which only a surface tangent to
//! `d` to all orders can give.
//!
//! Contacts of lower dimension: where the tie of a `min`/`max` is between operands that meet from
//! opposite sides (their derivatives along `d` have opposite signs), the step along `d` lands in
//! one of them, but the point may be a pinch (two balls touching at a point, two cylinders along a
//! line) rather than a shared face. The solid there is then decided by its regularised meaning:
//! the point is settled with the solid's interior only if the solid has no exterior points on both
//! sides of it, along a direction of the contact plane or one of the 13 lattice axes
//! (`Program::contact_probe`: points `1e-5` of the scale away: beyond rounding noise by far, beside a shared face's rim only within that
//! distance, and within a third of the interval margin, so pruned programs probe as the full one). A shared face keeps its samples inside (the union is one solid); a pinch takes them
//! outside (tangent balls stay two shells, as every exact Boolean engine has them; so do cubes sharing
//! only an edge); dually for
//! cavities touching inside a difference.
//!
//! The rule reads only the point and the field, so it is the same in every cell, brick and
//! thread. It is also the same for a pruned program inside its box: pruning drops an operand only
//! when it loses by more than the interval margin (`3e-5` of the scale, fifteen times the tie
//! tolerance), and then the full program never picks it either.

use super::{Instr, Program};
use crate::primitive::Shape;
use glam::DVec3;

/// The fixed generic direction of the perturbation, a unit vector chosen by search to make the
/// smallest `|d·n|` over the unit normals `n` of integer vectors with components in `−4..=4` as
/// large as possible (0.0125): never tangent to a face of a lattice-aligned model.
pub const PERTURBATION: DVec3 = DVec3::new(
    0.641_782_681_245_000_5,
    0.659_467_449_262_134_4,
    0.391_430_291_900_961_6,
);

/// Where a zero of the field lies, as [`Program::zero_side`] settles it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ZeroSide {
    /// Inside the solid: a face shared inside a union, an edge or corner of a stack.
    Inside,
    /// Outside the solid: a cutter flush with a face, a pinch of tangent operands.
    Outside,
    /// On a surface no other operand touches; the polygonizer decides from the lattice.
    Surface,
}

/// Scratch slot of [`Program::zero_side`]: value, derivative along [`PERTURBATION`], and
/// whether the value came through a contact (see the module docs).
pub type ZeroSlot = (f64, f64, bool);

/// Values closer than this are ties (twice the samplers' single-precision noise band at the same
/// coordinate scale).
pub fn tie_tolerance(p: DVec3) -> f64 {
    2e-6 * (1.0 + p.abs().max_element())
}

impl Program {
    /// Where the (numerically) zero point `p` lies: [`ZeroSide::Inside`] or
    /// [`ZeroSide::Outside`] when operands meet there (whether the solid contains `p + ε·`
    /// [`PERTURBATION`] for small `ε > 0`, unless the contact is a pinch), or
    /// [`ZeroSide::Surface`] on a surface no other operand touches. A point whose value lies
    /// outside the tie band takes its sign. `slots` is scratch (resized as needed).
    pub fn zero_side(&self, p: DVec3, slots: &mut Vec<ZeroSlot>) -> ZeroSide {
        let tol = tie_tolerance(p);
        let step = 1e-7 * (1.0 + p.abs().max_element());
        let q = p + PERTURBATION * step;
        slots.clear();
        slots.resize(self.register_count, (0.0, 0.0, false));
        // Lexicographic order on (value, derivative), values within `tol` tying. The flag says
        // that the value came through a tie of operands meeting from opposite sides (a contact).
        let less = |x: ZeroSlot, y: ZeroSlot| {
            if (x.0 - y.0).abs() <= tol {
                x.1 < y.1
            } else {
                x.0 < y.0
            }
        };
        let opposed = |x: ZeroSlot, y: ZeroSlot| (x.0 - y.0).abs() <= tol && x.1 * y.1 < 0.0;
        for (i, ins) in self.instrs.iter().enumerate() {
            let r = |v: u32| self.regs[v as usize] as usize;
            let v = match *ins {
                Instr::Leaf { prim, frame } => {
                    let f = &self.frames[frame as usize];
                    let s = &self.primitives[prim as usize];
                    let v0 = s.value(f.apply(p));
                    let v1 = s.value(f.apply(q));
                    (f.sigma * v0, f.sigma * (v1 - v0) / step, false)
                }
                Instr::Min(a, b) => {
                    let (x, y) = (slots[r(a)], slots[r(b)]);
                    let w = if less(y, x) { y } else { x };
                    (w.0, w.1, w.2 || opposed(x, y))
                }
                Instr::Max(a, b) => {
                    let (x, y) = (slots[r(a)], slots[r(b)]);
                    let w = if less(x, y) { y } else { x };
                    (w.0, w.1, w.2 || opposed(x, y))
                }
                Instr::Neg(a) => {
                    let x = slots[r(a)];
                    (-x.0, -x.1, x.2)
                }
                Instr::SmoothMin(a, b, k) => {
                    let (x, y, rad) = (slots[r(a)], slots[r(b)], k.get());
                    let h = (rad - (x.0 - y.0).abs()).max(0.0) / rad;
                    let (lo, hi) = if less(y, x) { (y, x) } else { (x, y) };
                    let w = 0.5 * h;
                    let d = if h > 0.0 {
                        lo.1 * (1.0 - w) + hi.1 * w
                    } else {
                        lo.1
                    };
                    (super::smooth_min(x.0, y.0, rad), d, lo.2)
                }
                Instr::Abs(a) => {
                    let x = slots[r(a)];
                    if less(x, (0.0, 0.0, false)) {
                        (-x.0, -x.1, x.2)
                    } else {
                        x
                    }
                }
                Instr::AddConst(a, k) => {
                    let x = slots[r(a)];
                    (x.0 + k.get(), x.1, x.2)
                }
                Instr::Const(c) => (c.value(), 0.0, false),
            };
            slots[self.regs[i] as usize] = v;
        }
        let (v, d, contact) = slots[*self.regs.last().expect("non-empty") as usize];
        let side = |inside: bool| {
            if inside {
                ZeroSide::Inside
            } else {
                ZeroSide::Outside
            }
        };
        if v.abs() > tol {
            return side(v < 0.0);
        }
        if !contact {
            return ZeroSide::Surface;
        }
        let inside = d < 0.0;
        side(inside != self.contact_probe(p, inside))
    }

    /// Whether the zero point `p`, settled `inside` (or not) by the step along [`PERTURBATION`]
    /// across a contact of two operands, is a pinch: the field has the other sign beside `p`
    /// within the contact plane (the plane normal to the gradient a short step along the
    /// perturbation, inside one operand). See the module docs.
    fn contact_probe(&self, p: DVec3, inside: bool) -> bool {
        let scale = 1.0 + p.abs().max_element();
        let eta = 1e-5 * scale;
        let noise = 1e-12 * scale;
        let mut slots = Vec::new();
        // The analytic gradient at `p`: that of the operand each min/max picks there, which at a
        // contact of opposite operands is the contact plane's normal.
        let n = self
            .value_gradient_with(p, &mut Vec::new())
            .1
            .normalize_or_zero();
        if n == DVec3::ZERO {
            return false;
        }
        let t1 = n.any_orthonormal_vector();
        let t2 = n.cross(t1);
        // Opposite pairs of directions: the contact plane (where a pinch of curved operands
        // shows, at second order), then the 13 lattice axes (where an edge contact of polytopes
        // shows: its empty wedges are opposite). A pinch has the other sign on both sides of
        // `p` along one of them; a shared face has it on neither (every direction off the face
        // enters an operand), a corner or seam of the solid's surface on one side only.
        let lattice = (0..13).map(|i| {
            DVec3::new(
                (i % 3) as f64 - 1.0,
                (i / 3 % 3) as f64 - 1.0,
                (i / 9) as f64 - 1.0,
            )
            .normalize()
        });
        let mut other = |t: DVec3| {
            let v = self.value_with(p + t * eta, &mut slots);
            if inside { v > noise } else { v < -noise }
        };
        [t1, t2]
            .into_iter()
            .chain(lattice)
            .any(|t| other(t) && other(-t))
    }
}
