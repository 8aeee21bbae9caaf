//! The motion `M(t)` of the swept solid: its origin carried to the path point `C(t)`, turned by
//! the rotation-minimising frame relative to the frame at the start (or not turned: `fixed`). The
//! frames are the sweep's (double reflection) at the fine parameters, joined by the shortest
//! rotation between consecutive ones at constant angular speed.

use super::SweptFrame;
use crate::curve::{Curve3, Parametric};
use crate::primitive::sweep::Frames;
use glam::{DAffine3, DMat3, DQuat, DVec3};

/// Fine steps per Bézier piece of the path over which the frames are propagated and the speed
/// is sampled.
pub(super) const STEPS_PER_PIECE: usize = 64;
/// Fine steps over the whole domain of a formula curve (it has no pieces).
const FORMULA_STEPS: usize = 4096;
/// The most fine steps over a path of many pieces.
const MAX_STEPS: usize = 1 << 17;

/// The rigid motion of the solid along the path.
pub(crate) struct Motion<'a> {
    path: &'a Parametric,
    /// The rotation part of `M(t)` at each fine parameter (the rotation-minimising frame's axes
    /// there times the inverse of those at the start); none for a fixed frame. Between fine
    /// parameters the rotation turns at constant angular speed along the shortest arc from one
    /// to the next (`slerp`), so its turning over any part of a step is exactly known.
    rotations: Option<Vec<DQuat>>,
    /// The fine parameters, increasing from the domain's start to its end.
    pub(super) fine: Vec<f64>,
}

impl<'a> Motion<'a> {
    /// The motion along `path` with `frame`.
    pub(crate) fn new(path: &'a Parametric, frame: SweptFrame) -> Motion<'a> {
        let fine = fine_params(path);
        let (t0, t1) = path.domain();
        let rotations = match frame {
            SweptFrame::Fixed => None,
            SweptFrame::Rmf => {
                let (a, b) = (path.jet(t0), path.jet(t1));
                // A closed path that ends along its start tangent gets the holonomy correction
                // (the last copy then matches the first); otherwise the frame is left free.
                let closed = path.is_closed()
                    && a.d1.normalize_or_zero().dot(b.d1.normalize_or_zero()) > 1.0 - 1e-9;
                let frames = Frames::from_jets(|t| path.jet(t), &fine, closed);
                let axes = |t: f64| {
                    let j = path.jet(t);
                    let f = frames.at(t, j.point, j.d1);
                    DMat3::from_cols(f.u, f.v, f.t)
                };
                let start = axes(t0).transpose();
                Some(
                    fine.iter()
                        .map(|&t| DQuat::from_mat3(&(axes(t) * start)).normalize())
                        .collect(),
                )
            }
        };
        Motion {
            path,
            rotations,
            fine,
        }
    }

    /// The fine step holding `t` and where `t` lies in it (0 to 1).
    fn step(&self, t: f64) -> (usize, f64) {
        let n = self.fine.len();
        let i = self
            .fine
            .partition_point(|&f| f <= t)
            .saturating_sub(1)
            .min(n.saturating_sub(2));
        if n < 2 {
            return (0, 0.0);
        }
        let (a, b) = (self.fine[i], self.fine[i + 1]);
        (i, ((t - a) / (b - a)).clamp(0.0, 1.0))
    }

    /// The rotation part of `M(t)`.
    pub(crate) fn rotation(&self, t: f64) -> DMat3 {
        match &self.rotations {
            None => DMat3::IDENTITY,
            Some(q) if q.len() < 2 => DMat3::from_quat(q[0]),
            Some(q) => {
                let (i, s) = self.step(t);
                DMat3::from_quat(q[i].slerp(q[i + 1], s))
            }
        }
    }

    /// `M(t)`: child coordinates to world coordinates.
    pub(crate) fn at(&self, t: f64) -> DAffine3 {
        DAffine3::from_mat3_translation(self.rotation(t), self.path.point(t))
    }

    /// The speed `|C'(t)|` of the path.
    pub(super) fn speed(&self, t: f64) -> f64 {
        self.path.jet(t).d1.length()
    }

    /// The angle the rotation turns through over fine step `i` (radians; 0 for a fixed frame).
    pub(super) fn step_turn(&self, i: usize) -> f64 {
        match &self.rotations {
            None => 0.0,
            Some(q) => {
                let r = q[i].inverse() * q[i + 1];
                // The shortest arc, as slerp takes it.
                2.0 * r.xyz().length().atan2(r.w.abs())
            }
        }
    }

    /// A bound of the path's speed over `[a, b]` for a formula curve (see
    /// [`crate::curve::FormulaCurve::speed_bound`]); `None` for other paths or no bound.
    pub(super) fn formula_speed(&self, a: f64, b: f64) -> Option<f64> {
        match self.path {
            Parametric::Formula(f) => f.speed_bound(a, b),
            Parametric::Curve(_) => None,
        }
    }

    /// The path's Bézier pieces (none for a formula curve).
    pub(super) fn pieces(&self) -> Option<Vec<crate::curve::BezierPiece>> {
        self.path.pieces()
    }
}

/// The fine parameters: [`STEPS_PER_PIECE`] equal steps over every Bézier piece (fewer when the
/// path has very many pieces), [`FORMULA_STEPS`] over a formula curve's domain.
fn fine_params(path: &Parametric) -> Vec<f64> {
    let (t0, t1) = path.domain();
    let spans: Vec<(f64, f64)> = match path {
        Parametric::Curve(c) => c.pieces().iter().map(|p| (p.t0, p.t1)).collect(),
        Parametric::Formula(_) => vec![(t0, t1)],
    };
    let per = if matches!(path, Parametric::Formula(_)) {
        FORMULA_STEPS
    } else {
        (MAX_STEPS / spans.len().max(1)).clamp(4, STEPS_PER_PIECE)
    };
    let mut fine = vec![t0];
    for (a, b) in spans {
        for k in 1..=per {
            let t = a + (b - a) * k as f64 / per as f64;
            if t > *fine.last().expect("non-empty") {
                fine.push(t);
            }
        }
    }
    if *fine.last().expect("non-empty") < t1 {
        fine.push(t1);
    }
    fine
}

/// The largest distance from the origin to a point of the box with corners `min`, `max`.
pub(super) fn radius_about_origin(min: DVec3, max: DVec3) -> f64 {
    min.abs().max(max.abs()).length()
}
