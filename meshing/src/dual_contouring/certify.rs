//! Why dual contouring's triangles never intersect, and the local tests that keep it so.
//!
//! Every piece of the surface inside a cell is held in a *cone* from the cell's patch vertex `v`
//! (strictly inside the cell) over a *zone* on the cell's boundary. Cones from one apex over zones
//! with disjoint interiors are disjoint but for their common boundary, cells are disjoint but for
//! their faces, so two triangles can meet only where the argument says they share an edge or a
//! vertex.
//!
//! - Zones. A crossing edge `E` owns a zone on each of its four faces. On a face whose one
//!   segment joins `E` to another crossing edge `E'`, the dual edge between the two cells crosses
//!   the face at a point `q` (strictly inside it, as both vertices are strictly inside their
//!   cells), and a separator through `q` splits the face: from the corner `E` and `E'` share
//!   through `q` to the opposite corner ([`FaceKind::Low`], [`FaceKind::High`]), or along `E`
//!   through `q` when `E'` is the far edge ([`FaceKind::Far`]). On an ambiguous face each segment
//!   gets the half of the face on the side of the corner it cuts off, and its two edges split that
//!   half from the corner through the segment's `q` to the face centre: this needs `q` strictly
//!   inside the half, else the dual edge is routed through a face vertex that is
//!   ([`super::faces::DualFace::crossing_ok`]). The cut-off corner is the inside corner the
//!   segment's edges share, or the outside one where the asymptotic decider joins the face's
//!   inside corners ([`super::patches::cut_corner`]): a joined face has the segments of a
//!   separated face with the signs flipped, and nothing here depends on which side is inside, so
//!   the halves, zones and tests are the same, with `E`'s segment cutting off its outside end
//!   instead of its inside end ([`FaceKind::of`]).
//! - A quad split into two triangles along a diagonal lies in the cones of its zones when, in the
//!   cell whose quadrant the diagonal passes through (seen along `E`), the diagonal passes
//!   between `E` and that cell's vertex, and where the diagonal crosses that cell's two faces the
//!   triangle from all of `E` to the crossing lies in `E`'s zone ([`certify`]). The other pieces
//!   are then cones from their vertices over the trace of the quad on the faces.
//! - A quad fanned from a point `p` strictly inside `E` (triangles `p, vᵢ, vᵢ₊₁`) always lies in
//!   its cones: the pieces are `p, vᵢ, q` with `q` on the face. This is the fallback of every quad
//!   the certificate rejects, of quads around ambiguous faces or touching cells with several
//!   patches, and of polygons through face vertices.
//! - A cell with several patches: each patch's vertex, crossings and dual-edge crossings stay
//!   strictly on its own side of the plane separating it from each other patch
//!   ([`super::patches::Patches::separators`]), so their cones cannot meet. Every configuration
//!   the decider can give has such planes; the only ones without (two interlocked patches)
//!   would need one pair of opposite faces joined and another separated, which the decider
//!   never gives ([`super::patches::reachable`]); the pinch check
//!   ([`crate::marching_cubes::pinch`]) can, and a run with such a cell claims nothing.
//! - A single patch whose loop winds around the cell through joined faces (marching cubes fans
//!   it from a centre vertex) is no different: its cones share one apex, and cones from one
//!   apex strictly inside the cell over disjoint zones are disjoint whatever the loop's shape.
//!
//! The tests run in floating point on the final coordinates with a margin ([`EPS`], in cells)
//! far above their rounding error, so what they certify holds exactly.

use glam::{DVec2, DVec3};

/// Crossings are kept at least this far (cells) from the samples.
pub(crate) const CROSSING_MARGIN: f64 = 1e-3;
/// Patch vertices are kept at least this far (cells) inside their cell.
pub(crate) const VERTEX_MARGIN: f64 = 1e-5;
/// Patch vertices of cells with several patches stay at least this far (cells) inside their
/// separating half-spaces (crossings are at least [`CROSSING_MARGIN`] inside).
pub(crate) const SEPARATOR_MARGIN: f64 = 1e-4;
/// Margin of the floating-point tests (cells).
pub(crate) const EPS: f64 = 1e-9;

/// The other crossing edge of the segment through `E` on one of `E`'s faces, in face
/// coordinates `(s, t)`: `s` the distance from `E` (0 to 1), `t` along `E` from its lower sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum FaceKind {
    /// The far edge `s = 1`.
    Far,
    /// The edge `t = 0` (shares `E`'s lower end).
    Low,
    /// The edge `t = 1` (shares `E`'s upper end).
    High,
    /// Two segments on the face; `E`'s segment cuts off its lower end (with the edge `t = 0`).
    AmbiguousLow,
    /// Two segments on the face; `E`'s segment cuts off its upper end (with the edge `t = 1`).
    AmbiguousHigh,
}

impl FaceKind {
    /// The kind from the inside flags of the face corners: `E`'s ends `e0` (`t = 0`), `e1`, and
    /// the far corners `f0` (`t = 0`), `f1`. `E` crosses (`e0 != e1`). On an ambiguous face,
    /// `joined` says the face joins its inside corners: `E`'s segment then cuts off `E`'s outside
    /// end instead of its inside end (ignored on other faces).
    pub fn of(e0: bool, e1: bool, f0: bool, f1: bool, joined: bool) -> Self {
        if e0 == f1 && e1 == f0 {
            if e0 != joined {
                FaceKind::AmbiguousLow
            } else {
                FaceKind::AmbiguousHigh
            }
        } else if e0 != f0 {
            FaceKind::Low
        } else if e1 != f1 {
            FaceKind::High
        } else {
            FaceKind::Far
        }
    }

    /// True on a face with two segments.
    pub fn ambiguous(self) -> bool {
        matches!(self, FaceKind::AmbiguousLow | FaceKind::AmbiguousHigh)
    }
}

/// Local coordinates around a crossing edge `E`: `x` along the first other axis, `y` along the
/// second, `z` along `E`, in cells, from `E`'s lower sample.
#[derive(Debug, Clone, Copy)]
pub(crate) struct EdgeFrame {
    pub origin: DVec3,
    pub cell: f64,
    pub axes: [usize; 3],
}

impl EdgeFrame {
    pub fn local(&self, p: DVec3) -> DVec3 {
        let d = (p - self.origin) * (1.0 / self.cell);
        DVec3::new(d[self.axes[0]], d[self.axes[1]], d[self.axes[2]])
    }
}

/// One of the four faces around `E` in a quad's ring (between ring cells `k` and `k + 1`): the
/// plane `x = 0` (`on_x`) or `y = 0`, and its kind.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RingFace {
    pub on_x: bool,
    pub kind: FaceKind,
}

/// The point of segment `a`–`b` on the plane `p[axis] = 0` (set exactly).
fn on_plane(a: DVec3, b: DVec3, axis: usize) -> DVec3 {
    let t = a[axis] / (a[axis] - b[axis]);
    let mut p = a + (b - a) * t;
    p[axis] = 0.0;
    p
}

/// Face coordinates `(s, t)` of a point on the plane `x = 0` (`on_x`) or `y = 0`.
fn face_point(p: DVec3, on_x: bool) -> DVec2 {
    DVec2::new(if on_x { p.y.abs() } else { p.x.abs() }, p.z)
}

/// True when the triangle from all of `E` (`s = 0`) to `b` lies strictly inside `E`'s zone of a
/// face whose dual edge crosses at `q`, apart from `E` itself.
pub(crate) fn in_zone(kind: FaceKind, q: DVec2, b: DVec2) -> bool {
    let inside = |p: DVec2| p.x > EPS && p.x < 1.0 - EPS && p.y > EPS && p.y < 1.0 - EPS;
    if !inside(b) || !inside(q) {
        return false;
    }
    if kind == FaceKind::Far {
        return b.x < q.x - EPS;
    }
    // Mirror so that the corner `E` shares with the other edge of its segment is (0, 0); the
    // separator runs from there through q to `far` and `E` (0, 0)–(0, 1) lies on its left. On an
    // ambiguous face the segment keeps to its half s + t < 1 and `far` is the face centre.
    let high = matches!(kind, FaceKind::High | FaceKind::AmbiguousHigh);
    let m = |p: DVec2| if high { DVec2::new(p.x, 1.0 - p.y) } else { p };
    let (q, b) = (m(q), m(b));
    let far = if kind.ambiguous() {
        if q.x + q.y >= 1.0 - EPS || b.x + b.y >= 1.0 - EPS {
            return false;
        }
        DVec2::splat(0.5)
    } else {
        DVec2::ONE
    };
    // Left of the ray from the corner through q.
    if q.perp_dot(b) <= EPS {
        return false;
    }
    if q.y > q.x {
        // q above the corner's diagonal: the zone holds every such point.
        true
    } else {
        // Convex zone: also on E's side of the segment q → far.
        let d = far - q;
        d.perp_dot(b - q) > EPS * d.length().max(1.0)
    }
}

/// True when the quad `v` (local coordinates of the four ring vertices, ring order around `E`,
/// each strictly inside its quadrant cell) split along `v[0]`–`v[2]` (or `v[1]`–`v[3]` when
/// `other_diagonal`) lies in the cones of `E`'s zones; `faces[k]` is the face between ring cells
/// `k` and `k + 1`. When some ring cells hold several patches, `side(k, x)` says whether the
/// local point `x` is strictly on ring cell `k`'s patch's side of its separating planes, and every
/// corner of the quad's pieces in those cells must be. See the module docs.
pub(crate) fn certify(
    v: &[DVec3; 4],
    faces: &[RingFace; 4],
    other_diagonal: bool,
    side: Option<&dyn Fn(usize, DVec3) -> bool>,
) -> bool {
    let (i, j) = if other_diagonal { (1, 3) } else { (0, 2) };
    let (a, b) = (on_plane(v[i], v[j], 0), on_plane(v[i], v[j], 1));
    if !(a.is_finite() && b.is_finite()) {
        return false;
    }
    let q = |f: usize| on_plane(v[f], v[(f + 1) % 4], if faces[f].on_x { 0 } else { 1 });
    if a.y == 0.0 && b.x == 0.0 {
        // The diagonal meets E: the quad is a fan from that point.
        return side.is_none_or(|side| {
            (0..4).all(|k| side(k, v[k]) && side(k, a) && side(k, q(k)) && side(k, q((k + 3) % 4)))
        });
    }
    // The cell whose quadrant the diagonal passes through.
    let quadrant = (b.x > 0.0, a.y > 0.0);
    let Some(x) = (0..4).find(|&k| k != i && k != j && (v[k].x > 0.0, v[k].y > 0.0) == quadrant)
    else {
        return false;
    };
    // Its two faces, where the quad's trace bends at the diagonal's crossing.
    let bend = |f: usize| if faces[f].on_x { a } else { b };
    for f in [(x + 3) % 4, x] {
        let on_x = faces[f].on_x;
        if !in_zone(
            faces[f].kind,
            face_point(q(f), on_x),
            face_point(bend(f), on_x),
        ) {
            return false;
        }
    }
    // The diagonal passes between E and the vertex: where it meets the plane through E and the
    // vertex, that point lies in the triangle of the vertex and E.
    let w = DVec2::new(v[x].x, v[x].y);
    let (cb, ca) = (
        w.perp_dot(DVec2::new(b.x, b.y)),
        w.perp_dot(DVec2::new(a.x, a.y)),
    );
    let s = cb / (cb - ca);
    if !(0.0..=1.0).contains(&s) {
        return false;
    }
    let c = b + (a - b) * s;
    let r = DVec2::new(c.x, c.y).dot(w) / w.length_squared();
    let z = v[x].z;
    if !(r.is_finite() && r < 1.0 - EPS && c.z > z * r + EPS && c.z < 1.0 - (1.0 - z) * r - EPS) {
        return false;
    }
    let Some(side) = side else {
        return true;
    };
    // The corners of the pieces in each cell: its vertex, the dual-edge crossings and bends on
    // its faces, and the point p where the triangle on E's side of the diagonal meets E.
    let k1 = (x + 2) % 4;
    let (t0, t1, t2) = (v[i], v[k1], v[j]);
    let at = |p: DVec3| DVec2::new(p.x, p.y);
    let area = (at(t1) - at(t0)).perp_dot(at(t2) - at(t0));
    let w1 = at(t2).perp_dot(at(t0)) / area;
    let w2 = at(t0).perp_dot(at(t1)) / area;
    let pz = t0.z * (1.0 - w1 - w2) + t1.z * w1 + t2.z * w2;
    if !pz.is_finite() {
        return false;
    }
    let p = DVec3::new(0.0, 0.0, pz);
    (0..4).all(|k| {
        let bends = [(k + 3) % 4, k]
            .into_iter()
            .filter(|&f| f == x || f == (x + 3) % 4)
            .all(|f| side(k, bend(f)));
        bends && side(k, v[k]) && side(k, p) && side(k, q(k)) && side(k, q((k + 3) % 4))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring_faces(kind: FaceKind) -> [RingFace; 4] {
        // Ring cells in quadrants (-,-), (+,-), (+,+), (-,+): faces y=0? between (-,-) and
        // (+,-) the x sign changes, so the face is x = 0.
        [true, false, true, false].map(|on_x| RingFace { on_x, kind })
    }

    #[test]
    fn face_kinds() {
        for joined in [false, true] {
            // Faces with one segment do not depend on the decider.
            assert_eq!(
                FaceKind::of(true, false, true, false, joined),
                FaceKind::Far
            );
            assert_eq!(
                FaceKind::of(true, false, false, false, joined),
                FaceKind::Low
            );
            assert_eq!(
                FaceKind::of(true, false, true, true, joined),
                FaceKind::High
            );
        }
        assert_eq!(
            FaceKind::of(true, false, false, true, false),
            FaceKind::AmbiguousLow
        );
        assert_eq!(
            FaceKind::of(false, true, true, false, false),
            FaceKind::AmbiguousHigh
        );
        // Joined: the segment cuts off E's outside end.
        assert_eq!(
            FaceKind::of(true, false, false, true, true),
            FaceKind::AmbiguousHigh
        );
        assert_eq!(
            FaceKind::of(false, true, true, false, true),
            FaceKind::AmbiguousLow
        );
    }

    /// On every face of every crossing edge of every configuration the decider gives, the kind
    /// names the edge that the case table's loops join to `E` on that face.
    #[test]
    fn face_kinds_follow_the_case_table() {
        use super::super::patches::{Config, edge_number, patch_table, reachable};
        use crate::marching_cubes::table::{CONFIGS, corner_offset, edge_corners, edge_origin};
        let edge = |a: u8, b: u8| {
            let along = (a ^ b).trailing_zeros() as usize;
            edge_number(along, corner_offset(a & b))
        };
        let mut ambiguous = [0usize; 2];
        for config in (0..CONFIGS as Config).filter(|&c| reachable(c)) {
            let p = patch_table().get(config);
            if (config >> 8) as u8 & !p.ambiguous != 0 {
                continue; // not a distinct configuration
            }
            let sides: Vec<(u8, u8)> = (p.edges.iter())
                .flat_map(|l| (0..l.len()).map(move |k| (l[k], l[(k + 1) % l.len()])))
                .collect();
            let inside = |c: u8| config >> c & 1 == 1;
            for e in (0..12u8).filter(|&e| p.patch_of_edge[usize::from(e)] != u8::MAX) {
                let (a, _) = edge_origin(e);
                let (e0, e1) = edge_corners(e);
                for w in (0..3).filter(|&w| w != a) {
                    // The face spanned by E and axis w: the one across the third axis.
                    let fa = 3 - a - w;
                    let bit = 2 * fa + usize::from(e0 >> fa & 1);
                    let (f0, f1) = (e0 ^ 1 << w, e1 ^ 1 << w);
                    let kind = FaceKind::of(
                        inside(e0),
                        inside(e1),
                        inside(f0),
                        inside(f1),
                        p.joined >> bit & 1 == 1,
                    );
                    let partner = match kind {
                        FaceKind::Far => edge(f0, f1),
                        FaceKind::Low | FaceKind::AmbiguousLow => edge(e0, f0),
                        FaceKind::High | FaceKind::AmbiguousHigh => edge(e1, f1),
                    };
                    if kind.ambiguous() {
                        ambiguous[usize::from(p.joined >> bit & 1)] += 1;
                    }
                    assert!(
                        sides.contains(&(e, partner)) || sides.contains(&(partner, e)),
                        "config {config:#x} edge {e} face {bit}: {kind:?}"
                    );
                }
            }
        }
        assert!(ambiguous[0] > 0 && ambiguous[1] > 0);
    }

    /// A flat quad around the edge (the plane z = 0.5) is certified either way; a quad whose
    /// diagonal passes beyond the off-diagonal vertex (a fold) is not.
    #[test]
    fn flat_quads_pass_and_folds_fail() {
        let flat = [
            DVec3::new(-0.5, -0.5, 0.5),
            DVec3::new(0.5, -0.5, 0.5),
            DVec3::new(0.5, 0.5, 0.5),
            DVec3::new(-0.5, 0.5, 0.5),
        ];
        for kind in [FaceKind::Far, FaceKind::Low, FaceKind::High] {
            assert!(certify(&flat, &ring_faces(kind), false, None));
            assert!(certify(&flat, &ring_faces(kind), true, None));
        }
        // The diagonal 0–2 passes through cell 1's quadrant beyond its vertex, which sits near
        // the edge: triangle 0 1 2 folds over the other.
        let folded = [
            DVec3::new(-0.2, -0.9, 0.5),
            DVec3::new(0.1, -0.1, 0.5),
            DVec3::new(0.9, 0.2, 0.5),
            DVec3::new(-0.5, 0.4, 0.5),
        ];
        assert!(!certify(&folded, &ring_faces(FaceKind::Far), false, None));
        // Along the other diagonal the same quad is fine.
        assert!(certify(&folded, &ring_faces(FaceKind::Far), true, None));
        // Unless a cell's separating plane cuts its piece: ring cell 0 keeps x < -0.3.
        let side = |k: usize, p: DVec3| k != 0 || p.x < -0.3;
        assert!(!certify(
            &folded,
            &ring_faces(FaceKind::Far),
            true,
            Some(&side)
        ));
        let side = |k: usize, p: DVec3| k != 0 || p.x < 0.5;
        assert!(certify(
            &folded,
            &ring_faces(FaceKind::Far),
            true,
            Some(&side)
        ));
    }

    #[test]
    fn zones() {
        let q = DVec2::new(0.5, 0.5);
        assert!(in_zone(FaceKind::Far, q, DVec2::new(0.3, 0.9)));
        assert!(!in_zone(FaceKind::Far, q, DVec2::new(0.6, 0.1)));
        // Low: separator (0,0) → q → (1,1); E's side is above it.
        assert!(in_zone(FaceKind::Low, q, DVec2::new(0.2, 0.6)));
        assert!(!in_zone(FaceKind::Low, q, DVec2::new(0.6, 0.2)));
        // High mirrors t.
        assert!(in_zone(FaceKind::High, q, DVec2::new(0.2, 0.4)));
        assert!(!in_zone(FaceKind::High, q, DVec2::new(0.6, 0.8)));
        // Convex zone: q below the diagonal; a point left of the ray but right of q → (1, 1).
        let q = DVec2::new(0.8, 0.2);
        assert!(in_zone(FaceKind::Low, q, DVec2::new(0.5, 0.6)));
        assert!(!in_zone(FaceKind::Low, q, DVec2::new(0.95, 0.5)));
        // Ambiguous: the segment's half s + t < 1, separator (0, 0) → q → (0.5, 0.5).
        let q = DVec2::new(0.3, 0.1);
        assert!(in_zone(FaceKind::AmbiguousLow, q, DVec2::new(0.1, 0.5)));
        assert!(!in_zone(FaceKind::AmbiguousLow, q, DVec2::new(0.3, 0.8)));
        assert!(!in_zone(FaceKind::AmbiguousLow, q, DVec2::new(0.4, 0.05)));
        assert!(in_zone(
            FaceKind::AmbiguousHigh,
            DVec2::new(0.3, 0.9),
            DVec2::new(0.1, 0.5)
        ));
        assert!(!in_zone(
            FaceKind::AmbiguousLow,
            DVec2::new(0.6, 0.6),
            DVec2::new(0.1, 0.5)
        ));
    }
}
