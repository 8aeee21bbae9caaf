//! The motion `M(t)` of the swept solid: its origin carried to the path point `C(t)`, turned by
//! the rotation-minimising frame relative to the frame at the start (or not turned: `fixed`).

use super::SweptFrame;
use crate::curve::{Curve3, Parametric};
use crate::primitive::sweep::Frames;
use glam::{DAffine3, DMat3, DVec3};

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
    /// Rotation-minimising frames (none for a fixed frame).
    frames: Option<Frames>,
    /// The frame's axes at the start as columns (`u`, `v`, `t`), inverted by transposing.
    start: DMat3,
    /// The fine parameters, increasing from the domain's start to its end.
    pub(super) fine: Vec<f64>,
}

impl<'a> Motion<'a> {
    /// The motion along `path` with `frame`.
    pub(crate) fn new(path: &'a Parametric, frame: SweptFrame) -> Motion<'a> {
        let fine = fine_params(path);
        let (t0, t1) = path.domain();
        let frames = match frame {
            SweptFrame::Fixed => None,
            SweptFrame::Rmf => {
                let (a, b) = (path.jet(t0), path.jet(t1));
                // A closed path that ends along its start tangent gets the holonomy correction
                // (the last copy then matches the first); otherwise the frame is left free.
                let closed = path.is_closed()
                    && a.d1.normalize_or_zero().dot(b.d1.normalize_or_zero()) > 1.0 - 1e-9;
                Some(Frames::from_jets(|t| path.jet(t), &fine, closed))
            }
        };
        let mut m = Motion {
            path,
            frames,
            start: DMat3::IDENTITY,
            fine,
        };
        m.start = m.axes(t0);
        m
    }

    /// The frame's axes at `t` as the columns of a rotation (identity for a fixed frame).
    fn axes(&self, t: f64) -> DMat3 {
        match &self.frames {
            None => DMat3::IDENTITY,
            Some(frames) => {
                let j = self.path.jet(t);
                let f = frames.at(t, j.point, j.d1);
                DMat3::from_cols(f.u, f.v, f.t)
            }
        }
    }

    /// The rotation part of `M(t)`.
    pub(crate) fn rotation(&self, t: f64) -> DMat3 {
        self.axes(t) * self.start.transpose()
    }

    /// `M(t)`: child coordinates to world coordinates.
    pub(crate) fn at(&self, t: f64) -> DAffine3 {
        DAffine3::from_mat3_translation(self.rotation(t), self.path.point(t))
    }

    /// The speed `|C'(t)|` of the path.
    pub(super) fn speed(&self, t: f64) -> f64 {
        self.path.jet(t).d1.length()
    }

    /// True when the frame turns (rotation-minimising).
    pub(super) fn turns(&self) -> bool {
        self.frames.is_some()
    }
}

/// The angle of the rotation `a·bᵀ` (radians, in `[0, π]`).
pub(super) fn angle_between(a: DMat3, b: DMat3) -> f64 {
    let r = a * b.transpose();
    let trace = r.x_axis.x + r.y_axis.y + r.z_axis.z;
    ((trace - 1.0) * 0.5).clamp(-1.0, 1.0).acos()
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
