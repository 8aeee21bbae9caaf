//! The swept volume of a solid moving along a path: `S = ⋃ₜ M(t)·child`, where `M(t)` carries
//! the child's origin to the path point `C(t)` and turns it by the path's rotation-minimising
//! frame relative to the frame at the start (`SweptFrame::Rmf`, the frames of
//! [`crate::primitive::Sweep`]), or only translates it (`SweptFrame::Fixed`). At the start the
//! child is only moved: `M(t₀)·x = x + C(t₀)`.
//!
//! The field of `S` is `f(x) = min_t f_c(M(t)⁻¹x)`. It is built as the n-ary union (a `min`)
//! of `N` rigidly moved copies of the child at parameters `t₀ < t₁ < … < t_{N−1}`, chosen so that
//! between consecutive parameters every point of the child's bounding box travels at most the
//! tolerance `τ` (see `sample.rs` for how that motion is bounded: a proof from the control
//! points, or for formula curves from interval arithmetic on the derivative; an estimate only
//! where that range is unbounded, [`SweptVolume::proven`]). The sampled field `f_N`
//! then satisfies, with `L` the child field's Lipschitz constant (1 for the kernel's distance
//! fields and distance bounds):
//!
//! - `f ≤ f_N` everywhere (the copies are part of the motion), so `{f_N ≤ 0} ⊆ S`;
//! - `f_N(x) ≤ f(x) + L·τ/2` wherever the minimising child point `M(t*)⁻¹x` lies in the child's
//!   bounding box, in particular at every point of `S`: every `t*` has a sample within `τ/2` of
//!   travel, and `M(t_k)⁻¹x` is `M(t*)⁻¹x` moved by that travel;
//! - every point of `S` is within `τ/2` of the sampled union (Hausdorff distance `≤ τ/2`).
//!
//! The tree is an ordinary union of affine transforms of the shared child, so the Program's
//! intervals are those of the union (sound), and the octree's pruning keeps only the copies near
//! each brick. The default tolerance is the child box's diagonal over
//! [`DEFAULT_DIVISOR`]; more than [`MAX_COPIES`] copies, or a tree of more than
//! [`MAX_TREE_NODES`] nodes, is an error that names what to change, never a long wait.

mod error;
mod motion;
mod sample;

#[cfg(test)]
mod tests;

pub use error::SweptError;

use crate::curve::Parametric;
use crate::solid::{NodeKind, Solid};
use crate::transform::{Transform, TransformSpec};
use glam::DAffine3;

/// The most copies of the child a swept volume may hold.
pub const MAX_COPIES: usize = 4096;

/// The most nodes a swept volume's tree may have (copies × (child nodes + 1) + 1): a swept
/// volume nested in another would otherwise multiply the tree by thousands per level.
pub const MAX_TREE_NODES: usize = 1_000_000;

/// The default tolerance is the child's bounding-box diagonal divided by this.
pub const DEFAULT_DIVISOR: f64 = 50.0;

/// How the moving solid is oriented along the path.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SweptFrame {
    /// Turned by the rotation-minimising frame (relative to the frame at the start).
    #[default]
    Rmf,
    /// Translated only.
    Fixed,
}

impl SweptFrame {
    /// The name in the JSON format (`rmf`, `fixed`).
    pub fn name(self) -> &'static str {
        match self {
            SweptFrame::Rmf => "rmf",
            SweptFrame::Fixed => "fixed",
        }
    }

    /// The frame named `name` in the JSON format.
    pub fn from_name(name: &str) -> Option<SweptFrame> {
        match name {
            "rmf" => Some(SweptFrame::Rmf),
            "fixed" => Some(SweptFrame::Fixed),
            _ => None,
        }
    }
}

/// A swept volume: the tree and how it was sampled.
#[derive(Debug, Clone)]
pub struct SweptVolume {
    /// The union of the moved copies.
    pub solid: Solid,
    /// The tolerance used (the given one, or the default).
    pub tolerance: f64,
    /// The parameters of the copies, increasing.
    pub params: Vec<f64>,
    /// Whether the travel between copies is a proven bound (false where a formula path's
    /// derivative has no bounded range on some step, so its speed was estimated from samples).
    pub proven: bool,
}

/// The default tolerance for a child with bounding-box diagonal `diagonal`.
pub fn default_tolerance(diagonal: f64) -> f64 {
    diagonal / DEFAULT_DIVISOR
}

/// The swept volume of `child` moving along `path` with `frame`, sampled within `tolerance`
/// (default: [`default_tolerance`] of the child's box).
pub fn swept_volume(
    child: &Solid,
    path: &Parametric,
    frame: SweptFrame,
    tolerance: Option<f64>,
) -> Result<SweptVolume, SweptError> {
    let bbox = child.bbox();
    if !bbox.is_finite() && !bbox.is_empty() {
        return Err(SweptError::UnboundedChild);
    }
    let tolerance = match tolerance {
        Some(t) if t.is_finite() && t > 0.0 => t,
        Some(t) => return Err(SweptError::Tolerance(t)),
        None if bbox.is_empty() => 1.0,
        None => {
            let t = default_tolerance(bbox.size().length());
            if !(t.is_finite() && t > 0.0) {
                // A flat or point-like child: any positive default will do.
                1e-3 * (1.0 + bbox.max.abs().max(bbox.min.abs()).max_element())
            } else {
                t
            }
        }
    };
    let motion = motion::Motion::new(path, frame);
    let rho = if bbox.is_empty() {
        0.0
    } else {
        motion::radius_about_origin(bbox.min, bbox.max)
    };
    let bounds = sample::step_bounds(&motion, rho)?;
    let params = sample::choose(&motion.fine, &bounds.bounds, tolerance, MAX_COPIES)?;
    // The child's count is bounded: a nested swept volume passed this check itself.
    let child_nodes = child.node_count();
    let nodes = params
        .len()
        .saturating_mul(child_nodes.saturating_add(1))
        .saturating_add(1);
    if nodes > MAX_TREE_NODES {
        return Err(SweptError::TooLarge {
            copies: params.len(),
            child_nodes,
            nodes,
            limit: MAX_TREE_NODES,
        });
    }
    let mut copies = Vec::with_capacity(params.len());
    for &t in &params {
        let m = motion.at(t);
        let spec = TransformSpec::Affine(rows(&m));
        let transform = Transform::new(spec)?;
        copies.push(Solid::from_parts(
            NodeKind::Transform(Box::new(transform)),
            vec![child.clone()],
        ));
    }
    Ok(SweptVolume {
        solid: Solid::from_parts(NodeKind::Union, copies),
        tolerance,
        params,
        proven: bounds.proven,
    })
}

/// The map as 3 rows of `[A | t]`.
fn rows(m: &DAffine3) -> [[f64; 4]; 3] {
    let (a, t) = (m.matrix3, m.translation);
    [
        [a.x_axis.x, a.y_axis.x, a.z_axis.x, t.x],
        [a.x_axis.y, a.y_axis.y, a.z_axis.y, t.y],
        [a.x_axis.z, a.y_axis.z, a.z_axis.z, t.z],
    ]
}
