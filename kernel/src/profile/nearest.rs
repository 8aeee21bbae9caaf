//! The nearest edge of a profile's loops: the closest point of one edge, the best edge so far,
//! the signed result, and the even-odd crossing test, shared by the plain loop over every edge
//! (`polygon.rs`) and the edge index of polygons with many edges (`edges.rs`).

use glam::DVec2;

/// The nearest boundary point of a set of loops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Nearest {
    /// Signed distance (negative inside by the even-odd rule).
    pub distance: f64,
    /// Gradient of the signed distance (unit length).
    pub gradient: DVec2,
    /// Loop of the nearest edge.
    pub ring: usize,
    /// Index of the nearest edge's first corner within its loop.
    pub edge: usize,
    /// Position of the nearest point along that edge (0 at its first corner, 1 at the next).
    pub lambda: f64,
}

/// The point of the edge `a → b` nearest to `q`: its position `lambda` along the edge (0 at
/// `a`), the point, the edge vector and the squared distance (the one computation every distance
/// query shares, so all give the same bits).
#[inline]
pub(super) fn closest(a: DVec2, b: DVec2, q: DVec2) -> (f64, DVec2, DVec2, f64) {
    let e = b - a;
    let w = q - a;
    let l2 = e.length_squared();
    let lambda = if l2 > 0.0 {
        (w.dot(e) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let c = a + e * lambda;
    (lambda, c, e, (q - c).length_squared())
}

/// Whether the edge `a → b` crosses the ray from `q` towards `+x` (the even-odd rule's test).
#[inline]
pub(super) fn crosses(q: DVec2, a: DVec2, b: DVec2) -> bool {
    (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)
}

/// The nearest edge found so far by a distance query.
#[derive(Debug, Clone, Copy)]
pub(super) struct Best {
    /// Squared distance to the edge.
    pub d2: f64,
    /// Its loop.
    pub ring: usize,
    /// Its first corner within the loop.
    pub edge: usize,
    /// Position of the nearest point along it.
    pub lambda: f64,
    /// The nearest point.
    pub c: DVec2,
    /// The edge vector.
    pub e: DVec2,
}

impl Best {
    /// No edge yet.
    pub const NONE: Best = Best {
        d2: f64::INFINITY,
        ring: 0,
        edge: 0,
        lambda: 0.0,
        c: DVec2::ZERO,
        e: DVec2::X,
    };

    /// The signed distance and gradient from `q`, negative when `inside`.
    pub fn signed(self, inside: bool, q: DVec2) -> Nearest {
        let d = self.d2.sqrt();
        let away = if d > 0.0 {
            (q - self.c) / d
        } else {
            DVec2::new(self.e.y, -self.e.x).normalize_or(DVec2::X)
        };
        let (distance, gradient) = if inside { (-d, -away) } else { (d, away) };
        Nearest {
            distance,
            gradient,
            ring: self.ring,
            edge: self.edge,
            lambda: self.lambda,
        }
    }
}
