//! Tests of the parametric tessellations: counts from the stated formulas, closed and outward
//! (every edge used once in each direction, positive volume), measured chord error within the
//! stated bound, and volume converging to the exact value.

use super::*;
use crate::primitive::heightfield::{HeightField, HeightGrid, HeightSource};
use crate::primitive::{Shape, Torus};
use glam::{DVec2, DVec3};
use std::collections::HashMap;
use std::f64::consts::PI;

fn closed_oriented(m: &IndexedMesh) -> bool {
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &m.triangles {
        if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            return false;
        }
        for c in 0..3 {
            *directed.entry((t[c], t[(c + 1) % 3])).or_default() += 1;
        }
    }
    directed
        .iter()
        .all(|(&(a, b), &n)| n == 1 && directed.get(&(b, a)) == Some(&1))
}

fn volume(m: &IndexedMesh) -> f64 {
    (0..m.triangle_count())
        .map(|t| {
            let [a, b, c] = m.triangle_positions(t);
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

fn euler(m: &IndexedMesh) -> i64 {
    let mut edges = std::collections::HashSet::new();
    for t in &m.triangles {
        for c in 0..3 {
            edges.insert((t[c].min(t[(c + 1) % 3]), t[c].max(t[(c + 1) % 3])));
        }
    }
    m.vertex_count() as i64 - edges.len() as i64 + m.triangle_count() as i64
}

/// Closest point of triangle `abc` to the origin's distance (Ericson's region test).
fn distance_to_origin(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let p = DVec3::ZERO;
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a.length();
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b.length();
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return (a + ab * (d1 / (d1 - d3))).length();
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c.length();
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return (a + ac * (d2 / (d2 - d6))).length();
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))).length();
    }
    let denom = 1.0 / (va + vb + vc);
    (a + ab * (vb * denom) + ac * (vc * denom)).length()
}

#[test]
fn open_grid_has_the_counts_of_the_notes() {
    let m = regular_grid(5, 7, |u, v| DVec3::new(u, v, u * v)).unwrap();
    assert_eq!((m.vertex_count(), m.triangle_count()), (35, 2 * 4 * 6));
    // Wound along ∂f/∂u × ∂f/∂v = +z for a flat patch.
    for t in 0..m.triangle_count() {
        let [a, b, c] = m.triangle_positions(t);
        assert!((b - a).cross(c - a).z > 0.0);
    }
    assert!(regular_grid(1, 3, |u, v| DVec3::new(u, v, 0.0)).is_err());
}

#[test]
fn sphere_counts_chord_error_and_volume() {
    let r = 1.7;
    let mut last_err = f64::INFINITY;
    for n in [9usize, 17, 33, 65] {
        let t = sphere(r, n, n.div_ceil(2)).unwrap();
        let (nu, nv) = (n, n.div_ceil(2));
        assert_eq!(t.mesh.vertex_count(), (nu - 1) * (nv - 2) + 2);
        assert_eq!(t.mesh.triangle_count(), 2 * (nu - 1) * (nv - 2));
        assert!(closed_oriented(&t.mesh) && euler(&t.mesh) == 2);
        // The exact chord error: r minus the closest any triangle comes to the centre.
        let worst = (0..t.mesh.triangle_count())
            .map(|k| {
                let [a, b, c] = t.mesh.triangle_positions(k);
                r - distance_to_origin(a, b, c)
            })
            .fold(0.0, f64::max);
        let stated = t.chord_error.unwrap();
        assert!(
            worst <= stated && worst > 0.3 * stated,
            "{worst} vs {stated}"
        );
        let err = (4.0 / 3.0 * PI * r.powi(3) - volume(&t.mesh)).abs();
        assert!(err < 0.5 * last_err, "{err} vs {last_err}");
        last_err = err;
    }
    assert!(last_err / (4.0 / 3.0 * PI * r.powi(3)) < 5e-3);
    let (nu, nv) = chord::sphere_counts(r, 1e-3).unwrap();
    assert!(sphere(r, nu, nv).unwrap().chord_error.unwrap() <= 1e-3);
}

#[test]
fn ellipsoid_volume_converges() {
    let radii = DVec3::new(1.0, 0.6, 1.4);
    let exact = 4.0 / 3.0 * PI * radii.x * radii.y * radii.z;
    let t = ellipsoid(radii, 129, 65).unwrap();
    assert!(closed_oriented(&t.mesh));
    assert!((volume(&t.mesh) - exact).abs() / exact < 2e-3);
    let e = crate::primitive::Ellipsoid { radii };
    let worst = t
        .mesh
        .positions
        .iter()
        .map(|p| e.value(*p).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-12, "vertices lie on the ellipsoid");
}

#[test]
fn capsule_counts_and_volume() {
    let (r, l) = (0.5, 1.2);
    let exact = PI * r * r * l + 4.0 / 3.0 * PI * r * r * r;
    let mut last = f64::INFINITY;
    for (nu, nv) in [(9, 5), (17, 9), (33, 17), (65, 33)] {
        let t = capsule(r, l, nu, nv).unwrap();
        assert_eq!(t.mesh.vertex_count(), (nu - 1) * (nv - 1) + 2);
        assert_eq!(t.mesh.triangle_count(), 2 * (nu - 1) * (nv - 1));
        assert!(closed_oriented(&t.mesh) && euler(&t.mesh) == 2);
        let err = (volume(&t.mesh) - exact).abs();
        assert!(err < 0.5 * last);
        last = err;
        // Every vertex is on the capsule: distance r from the axis segment.
        for p in &t.mesh.positions {
            let q = DVec3::new(0.0, 0.0, p.z.clamp(-0.5 * l, 0.5 * l));
            assert!(((*p - q).length() - r).abs() < 1e-12);
        }
    }
    assert!(last / exact < 5e-3);
    assert!(capsule(r, l, 9, 6).is_err());
}

#[test]
fn torus_counts_chord_error_and_volume() {
    let (big, small) = (1.0, 0.3);
    let exact = 2.0 * PI * PI * big * small * small;
    let shape = Torus {
        major_radius: big,
        minor_radius: small,
    };
    let mut last = f64::INFINITY;
    for (nu, nv) in [(17, 9), (33, 17), (65, 33)] {
        let t = torus(big, small, nu, nv).unwrap();
        assert_eq!(t.mesh.vertex_count(), (nu - 1) * (nv - 1));
        assert_eq!(t.mesh.triangle_count(), 2 * (nu - 1) * (nv - 1));
        assert!(closed_oriented(&t.mesh) && euler(&t.mesh) == 0);
        // Sampled chord error (exact distance to the torus) within the stated bound.
        let mut worst = 0.0f64;
        for k in 0..t.mesh.triangle_count() {
            let [a, b, c] = t.mesh.triangle_positions(k);
            for &(u, v) in &[(1.0 / 3.0, 1.0 / 3.0), (0.5, 0.0), (0.0, 0.5), (0.5, 0.5)] {
                worst = worst.max(shape.value(a * (1.0 - u - v) + b * u + c * v).abs());
            }
        }
        assert!(
            worst <= t.chord_error.unwrap(),
            "{worst} vs {:?}",
            t.chord_error
        );
        let err = (volume(&t.mesh) - exact).abs();
        assert!(err < 0.5 * last);
        last = err;
    }
    assert!(last / exact < 1e-2);
}

#[test]
fn heightfield_solid_counts_chord_error_and_volume() {
    let rows = vec![
        vec![0.5, 0.8, 0.6],
        vec![0.9, 1.6, 0.7],
        vec![0.6, 1.1, 1.0],
        vec![0.4, 0.7, 0.9],
    ];
    let grid = HeightGrid::from_rows(&rows).unwrap();
    let mean = grid.values().iter().sum::<f64>() / 12.0;
    let (lo, hi) = (DVec2::new(-1.0, 0.0), DVec2::new(1.0, 1.5));
    let hf = HeightField::new(lo, hi, 0.1, HeightSource::Bezier(grid)).unwrap();
    // ∫∫ h = area × mean control height (each Bernstein polynomial integrates to 1/(n + 1)).
    let exact = (hi - lo).x * (hi - lo).y * (mean - 0.1);
    let mut last = f64::INFINITY;
    for n in [5usize, 9, 17, 33, 65] {
        let t = heightfield(&hf, n).unwrap();
        assert_eq!(t.mesh.vertex_count(), 2 * n * n);
        assert_eq!(t.mesh.triangle_count(), 4 * (n - 1) * (n - 1) + 8 * (n - 1));
        assert!(closed_oriented(&t.mesh) && euler(&t.mesh) == 2);
        let err = (volume(&t.mesh) - exact).abs();
        assert!(err < 0.5 * last || err < 1e-12, "n {n}: {err}");
        last = err;
        // Vertical distance from points on the top triangles to the surface.
        let stated = t.chord_error.unwrap();
        let mut worst = 0.0f64;
        for k in 0..t.mesh.triangle_count() {
            let [a, b, c] = t.mesh.triangle_positions(k);
            if a.z == 0.1 || b.z == 0.1 || c.z == 0.1 {
                continue;
            }
            let p = (a + b + c) / 3.0;
            worst = worst.max((p.z - hf.height(p.x, p.y)).abs());
        }
        assert!(worst <= stated, "{worst} vs {stated}");
    }
    assert!(last / exact < 1e-3);
}
