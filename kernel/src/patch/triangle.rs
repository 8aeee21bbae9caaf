//! Triangular Bézier patches (lecture notes 001): `p(u, v, w) = Σ_{i+j+k=n} n!/(i! j! k!) uⁱ vʲ wᵏ
//! p_ijk` over barycentric coordinates `u + v + w = 1`, evaluated by de Casteljau's algorithm on
//! the barycentric control net, and tessellated by a uniform subdivision of the parameter
//! triangle.

use super::error::PatchError;
use crate::IndexedMesh;
use glam::DVec3;

/// A triangular Bézier patch of degree `n` with `(n + 1)(n + 2)/2` control points `p_ijk`.
///
/// The corners are `p_n00` (at `u = 1`), `p_0n0` (`v = 1`) and `p_00n` (`w = 1`); the patch is
/// oriented like the triangle of those corners in that order.
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleBezier {
    degree: usize,
    points: Vec<DVec3>,
}

/// Position of `p_ijk` (`i = n − j − k`) in a net of degree `n`: by `k`, then `j`.
#[inline]
fn slot(n: usize, j: usize, k: usize) -> usize {
    k * (n + 1) - k * k.saturating_sub(1) / 2 + j
}

/// Number of control points of a net of degree `n`.
pub fn net_size(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
}

impl TriangleBezier {
    /// A patch of degree `n` from control points listed by `k` (0 to n), then `j` (0 to n − k);
    /// see [`TriangleBezier::index`].
    pub fn new(degree: usize, points: Vec<DVec3>) -> Result<Self, PatchError> {
        let expected = net_size(degree);
        if points.len() != expected {
            return Err(PatchError::ControlCount {
                degree,
                expected,
                got: points.len(),
            });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(PatchError::NonFinite {
                what: "control point",
                index,
            });
        }
        Ok(Self { degree, points })
    }

    /// A patch from a function of `(i, j, k)` giving each control point.
    pub fn from_fn(
        degree: usize,
        f: impl Fn(usize, usize, usize) -> DVec3,
    ) -> Result<Self, PatchError> {
        let mut points = Vec::with_capacity(net_size(degree));
        for k in 0..=degree {
            for j in 0..=degree - k {
                points.push(f(degree - j - k, j, k));
            }
        }
        Self::new(degree, points)
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The position of `p_ijk` in the control point list (`i + j + k = n`).
    pub fn index(&self, j: usize, k: usize) -> usize {
        slot(self.degree, j, k)
    }

    /// Control point `p_ijk` with `i = n − j − k`.
    pub fn control(&self, j: usize, k: usize) -> DVec3 {
        self.points[self.index(j, k)]
    }

    /// `p(u, v, w)` by de Casteljau's algorithm; `scratch` is reused between calls.
    pub fn point_with(&self, bary: DVec3, scratch: &mut Vec<DVec3>) -> DVec3 {
        let (u, v, w) = (bary.x, bary.y, bary.z);
        scratch.clear();
        scratch.extend_from_slice(&self.points);
        // Level r → r − 1 in place: entries are written at slot(r − 1, j, k) = slot(r, j, k) − k,
        // never after a later step reads them (reads are at slot(r, ·) ≥ slot(r, j, k)).
        for r in (1..=self.degree).rev() {
            for k in 0..r {
                for j in 0..r - k {
                    let p = scratch[slot(r, j, k)] * u
                        + scratch[slot(r, j + 1, k)] * v
                        + scratch[slot(r, j, k + 1)] * w;
                    scratch[slot(r - 1, j, k)] = p;
                }
            }
        }
        scratch[0]
    }

    /// `p(u, v, w)`.
    pub fn point(&self, bary: DVec3) -> DVec3 {
        self.point_with(bary, &mut Vec::with_capacity(self.points.len()))
    }

    /// The patch sampled at the barycentric grid `(s − j − k, j, k) / s` (`(s + 1)(s + 2)/2`
    /// vertices, `s²` triangles), oriented like the patch.
    pub fn tessellate(&self, s: usize) -> Result<IndexedMesh, PatchError> {
        if s == 0 || s > 4096 {
            return Err(PatchError::Count {
                what: "segments",
                got: s,
                min: 1,
                max: 4096,
            });
        }
        let mut scratch = Vec::new();
        let mut positions = Vec::with_capacity(net_size(s));
        for k in 0..=s {
            for j in 0..=s - k {
                let (v, w) = (j as f64 / s as f64, k as f64 / s as f64);
                positions.push(self.point_with(DVec3::new(1.0 - v - w, v, w), &mut scratch));
            }
        }
        let mut triangles = Vec::with_capacity(s * s);
        grid_triangles(s, |j, k| slot(s, j, k) as u32, &mut triangles);
        Ok(IndexedMesh::new(positions, triangles))
    }
}

/// The `s²` triangles of the barycentric grid of `s` segments, with vertex `(j, k)` numbered by
/// `id`: "upward" `(j, k), (j + 1, k), (j, k + 1)` and "downward" `(j + 1, k), (j + 1, k + 1),
/// (j, k + 1)`, both wound like the corners `u, v, w`.
pub(crate) fn grid_triangles(s: usize, id: impl Fn(usize, usize) -> u32, out: &mut Vec<[u32; 3]>) {
    for k in 0..s {
        for j in 0..s - k {
            out.push([id(j, k), id(j + 1, k), id(j, k + 1)]);
            if j + k + 1 < s {
                out.push([id(j + 1, k), id(j + 1, k + 1), id(j, k + 1)]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::patch::bernstein::binomial;

    fn sample_patch(n: usize) -> TriangleBezier {
        TriangleBezier::from_fn(n, |i, j, k| {
            DVec3::new(
                i as f64,
                j as f64 * 1.5,
                ((i * 7 + j * 3 + k) % 5) as f64 * 0.2,
            )
        })
        .unwrap()
    }

    #[test]
    fn de_casteljau_matches_the_bernstein_sum() {
        for n in 0..7 {
            let patch = sample_patch(n);
            for &(v, w) in &[
                (0.0f64, 0.0f64),
                (0.2, 0.3),
                (0.5, 0.5),
                (0.1, 0.85),
                (1.0, 0.0),
            ] {
                let u = 1.0 - v - w;
                let mut sum = DVec3::ZERO;
                for k in 0..=n {
                    for j in 0..=n - k {
                        let i = n - j - k;
                        let c = binomial(n, i) * binomial(n - i, j);
                        let b = c * u.powi(i as i32) * v.powi(j as i32) * w.powi(k as i32);
                        sum += patch.control(j, k) * b;
                    }
                }
                let p = patch.point(DVec3::new(u, v, w));
                assert!((p - sum).length() < 1e-12, "n {n}: {p} vs {sum}");
            }
        }
    }

    #[test]
    fn corners_and_linear_patch() {
        let patch = sample_patch(3);
        assert_eq!(patch.point(DVec3::X), patch.control(0, 0));
        assert_eq!(patch.point(DVec3::Y), patch.control(3, 0));
        assert_eq!(patch.point(DVec3::Z), patch.control(0, 3));
        // Degree 1 is the flat triangle.
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::new(0.0, 2.0, 1.0));
        let flat = TriangleBezier::new(1, vec![a, b, c]).unwrap();
        let p = flat.point(DVec3::new(0.2, 0.3, 0.5));
        assert!((p - (a * 0.2 + b * 0.3 + c * 0.5)).length() < 1e-15);
    }

    #[test]
    fn tessellation_counts_and_orientation() {
        let (a, b, c) = (DVec3::ZERO, DVec3::X, DVec3::Y);
        let flat = TriangleBezier::new(1, vec![a, b, c]).unwrap();
        let m = flat.tessellate(5).unwrap();
        assert_eq!((m.vertex_count(), m.triangle_count()), (21, 25));
        let mut area = 0.0;
        for t in 0..m.triangle_count() {
            let [p, q, r] = m.triangle_positions(t);
            let n = (q - p).cross(r - p);
            assert!(n.z > 0.0, "triangle {t} flipped");
            area += 0.5 * n.length();
        }
        assert!((area - 0.5).abs() < 1e-12);
        assert!(flat.tessellate(0).is_err());
        assert!(TriangleBezier::new(2, vec![a; 5]).is_err());
    }
}
