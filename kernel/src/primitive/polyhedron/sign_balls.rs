//! Signs shared between the points of a batch: a point's distance to a closed mesh bounds a ball
//! of points with its sign, so the mesh solid computes winding numbers only near the surface.

use glam::DVec3;

/// Points of a batch whose sign is known, each with its distance to the mesh: the open ball of
/// that radius around it holds no point of the surface, so for a closed mesh (every edge used
/// equally often in both directions) the exact winding number, an integer off the surface, is
/// constant on it, and any point inside the ball has the centre's sign. The balls are shrunk by
/// [`SignBalls::SHRINK`] against rounding of the distances. Only the last [`SignBalls::KEEP`]
/// points and the largest ball are kept: batches come from grid blocks, so a point's
/// neighbours are among the last points evaluated.
///
/// The classification this reuses is the fast winding number's (within 0.05 of the exact
/// integer away from the surface, see `winding.rs`), so reusing it gives the same sign as
/// computing it again.
#[derive(Default)]
pub(crate) struct SignBalls {
    recent: [(DVec3, f64, bool); SignBalls::KEEP],
    next: usize,
    len: usize,
    largest: Option<(DVec3, f64, bool)>,
}

impl SignBalls {
    /// Points kept besides the largest ball.
    const KEEP: usize = 16;
    /// The radius used, a fraction of the distance (far more than its rounding error).
    const SHRINK: f64 = 1.0 - 1e-9;

    /// The sign of a ball holding `p`, if any.
    pub(crate) fn sign_at(&self, p: DVec3) -> Option<bool> {
        let holds = |&(c, r, _): &(DVec3, f64, bool)| {
            let r = r * Self::SHRINK;
            p.distance_squared(c) < r * r
        };
        if let Some(ball) = self.largest.filter(holds) {
            return Some(ball.2);
        }
        self.recent[..self.len]
            .iter()
            .find(|b| holds(b))
            .map(|b| b.2)
    }

    /// Remembers that `p`, at `distance` from the surface, is `inside` or not.
    pub(crate) fn push(&mut self, p: DVec3, distance: f64, inside: bool) {
        self.recent[self.next] = (p, distance, inside);
        self.next = (self.next + 1) % Self::KEEP;
        self.len = (self.len + 1).min(Self::KEEP);
        if self.largest.is_none_or(|(_, r, _)| distance > r) {
            self.largest = Some((p, distance, inside));
        }
    }
}
