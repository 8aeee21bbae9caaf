//! Exact orientation predicates (Shewchuk's adaptive arithmetic, from the `robust` crate): the
//! sign of `orient3d` says on which side of a plane a point lies, `orient2d` on which side of a
//! line, with no rounding error. 2D tests run on a coordinate projection of a plane (dropping
//! one axis copies coordinates, so it is exact as well).

use glam::DVec3;
use robust::{Coord, Coord3D, orient2d, orient3d};

/// The sign (-1, 0 or 1) of the volume of the tetrahedron `abcd` (0 when coplanar).
///
/// Four points with one coordinate equal are coplanar, and the determinant of their differences
/// has a zero column: exactly 0, decided here without the adaptive stages, which an exact zero
/// runs to the end (their slowest case). Flat faces of CAD models lie in such planes.
pub(crate) fn orient(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
    if (0..3).any(|k| a[k] == b[k] && a[k] == c[k] && a[k] == d[k]) {
        return 0;
    }
    let k = |p: DVec3| Coord3D {
        x: p.x,
        y: p.y,
        z: p.z,
    };
    sign(orient3d(k(a), k(b), k(c), k(d)))
}

/// A projection onto a coordinate plane: the two kept axes (bytes: the search keeps one per
/// triangle).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Projection([u8; 2]);

impl Projection {
    /// A projection under which the triangle keeps a non-zero area, preferring the axis its
    /// normal is most aligned with; `None` when the triangle is exactly collinear (degenerate).
    pub(crate) fn of([a, b, c]: [DVec3; 3]) -> Option<Self> {
        let n = (b - a).cross(c - a).abs();
        let mut axes = [0, 1, 2];
        axes.sort_by(|&i, &j| n[j].total_cmp(&n[i]));
        axes.into_iter()
            .map(Self::dropping)
            .find(|p| p.orient(a, b, c) != 0)
    }

    /// The projection dropping `axis` (0, 1 or 2; larger reads as 2), its kept axes in cyclic
    /// order, so a triangle whose normal points along `+axis` turns counter-clockwise.
    pub(crate) fn dropping(axis: usize) -> Self {
        Self(match axis {
            0 => [1, 2],
            1 => [2, 0],
            _ => [0, 1],
        })
    }

    /// The sign of the projected triangle `abc` (1: counter-clockwise). Three points with one
    /// projected coordinate equal are collinear: exactly 0, without the adaptive stages.
    pub(crate) fn orient(self, a: DVec3, b: DVec3, c: DVec3) -> i8 {
        if self
            .0
            .iter()
            .map(|&k| usize::from(k))
            .any(|k| a[k] == b[k] && a[k] == c[k])
        {
            return 0;
        }
        sign(orient2d(self.coord(a), self.coord(b), self.coord(c)))
    }

    /// The two kept axes, in order.
    pub(crate) fn axes(self) -> [usize; 2] {
        self.0.map(usize::from)
    }

    /// The projected coordinates of `p`.
    fn coord(self, p: DVec3) -> Coord<f64> {
        Coord {
            x: p[usize::from(self.0[0])],
            y: p[usize::from(self.0[1])],
        }
    }

    /// True when `p`, known to be on the line through `a` and `b`, lies on the closed segment
    /// `[a, b]` (compared coordinate by coordinate, exact).
    pub(crate) fn within(self, p: DVec3, a: DVec3, b: DVec3) -> bool {
        self.0
            .iter()
            .map(|&k| usize::from(k))
            .all(|k| p[k] >= a[k].min(b[k]) && p[k] <= a[k].max(b[k]))
    }
}

/// The sign of `x` as -1, 0 or 1.
fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// True when the signs include both -1 and 1.
pub(crate) fn mixed(signs: &[i8]) -> bool {
    signs.contains(&1) && signs.contains(&-1)
}
