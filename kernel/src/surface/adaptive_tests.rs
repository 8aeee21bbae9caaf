//! Curvature-adaptive tessellation: the chord-error bound holds where measured, the mesh has no
//! T-junction (the welded sheet's boundary is the domain's), seams close, and flat regions take
//! far fewer triangles than the regular grid.

use super::adaptive::fan_bound;
use super::close::{boundary_edges, signed_volume};
use super::sample::grid;
use super::*;
use crate::IndexedMesh;
use crate::primitive::NoMeshResolver;
use glam::{DVec2, DVec3};
use std::f64::consts::PI;

/// A 7 × 7 Bézier patch over [0, 6]², flat but for one raised control point near a corner.
fn bump() -> SurfaceKind {
    let mut pts = Vec::new();
    for j in 0..7 {
        for i in 0..7 {
            let z = if (i, j) == (1, 1) { 3.0 } else { 0.0 };
            pts.push(DVec3::new(i as f64, j as f64, z));
        }
    }
    SurfaceKind::Bezier(TensorSurface::bezier([7, 7], pts).unwrap())
}

/// An adaptively tessellated surface node.
fn adaptive(kind: SurfaceKind, closure: Closure, tolerance: f64) -> SurfaceSpec {
    SurfaceSpec {
        kind,
        closure,
        tolerance: Some(tolerance),
        segments: None,
        adaptive: true,
    }
}

/// A slab of `thickness` about the surface.
fn slab(thickness: f64) -> Closure {
    Closure::Thickness {
        thickness,
        side: Side::Both,
    }
}

/// The largest distance between the surface and the (unwelded) mesh at 15 barycentric points of
/// every triangle, each mapped through the triangle's parameters.
fn measured_chord(kind: &SurfaceKind, mesh: &IndexedMesh, params: &[DVec2]) -> f64 {
    let mut worst = 0.0f64;
    for t in &mesh.triangles {
        for a in 0..=4 {
            for b in 0..=4 - a {
                let l = [a as f64 / 4.0, b as f64 / 4.0, (4 - a - b) as f64 / 4.0];
                let x: DVec2 = (0..3).map(|k| params[t[k] as usize] * l[k]).sum();
                let lin: DVec3 = (0..3).map(|k| mesh.positions[t[k] as usize] * l[k]).sum();
                let s = kind.derivatives(x.x, x.y).unwrap().p;
                worst = worst.max(s.distance(lin));
            }
        }
    }
    worst
}

#[test]
fn fan_bound_is_the_grid_bound_on_right_triangles_and_half_the_long_edge_when_obtuse() {
    let (a, b) = (0.3, 0.7);
    let right = [DVec2::ZERO, DVec2::new(a, 0.0), DVec2::new(a, b)];
    assert!((fan_bound(right) - (a * a + b * b) / 8.0).abs() < 1e-15);
    let obtuse = [DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(1.0, 0.1)];
    assert!((fan_bound(obtuse) - 0.5 * 1.0).abs() < 1e-15);
    // Equilateral of side 1: R² = 1/3.
    let eq = [DVec2::ZERO, DVec2::X, DVec2::new(0.5, 0.75f64.sqrt())];
    assert!((fan_bound(eq) - 0.5 / 3.0).abs() < 1e-12);
}

#[test]
fn a_bump_meets_its_bound_with_far_fewer_triangles_and_no_t_junction() {
    let kind = bump();
    for tol in [1e-2, 1e-3] {
        let ((uniform, _, uniform_chord, _, _), _) = grid(&kind, Some(tol), false).unwrap();
        let ((mesh, _, chord, estimated, _), params) = grid(&kind, Some(tol), true).unwrap();
        let chord = chord.unwrap();
        assert!(!estimated);
        // Never worse than the grid (which stops at 256 segments, above 1e-3 here).
        assert!(
            chord <= tol.max(uniform_chord.unwrap()),
            "{chord} {uniform_chord:?} {tol}"
        );
        let measured = measured_chord(&kind, &mesh, &params);
        assert!(measured <= chord * (1.0 + 1e-9), "{measured} > {chord}");
        assert!(
            3 * mesh.triangles.len() < uniform.triangles.len(),
            "{} adaptive against {} uniform triangles",
            mesh.triangles.len(),
            uniform.triangles.len()
        );
        // Every boundary edge of the sheet lies on the domain's boundary: no crack inside.
        let mut s = adaptive(kind.clone(), slab(0.1), tol);
        let sheet = s.sheet(&NoMeshResolver).unwrap();
        let on_edge = |p: DVec3| {
            p.x.abs() < 1e-12
                || p.y.abs() < 1e-12
                || (p.x - 6.0).abs() < 1e-12
                || (p.y - 6.0).abs() < 1e-12
        };
        for (a, b) in boundary_edges(&sheet.mesh) {
            let (p, q) = (
                sheet.mesh.positions[a as usize],
                sheet.mesh.positions[b as usize],
            );
            assert!(on_edge(p) && on_edge(q), "inner boundary edge {p} {q}");
        }
        // Closed into a slab: the same volume as the uniform slab's, within the chord errors.
        let adaptive_volume = signed_volume(&s.closed_mesh(&NoMeshResolver).unwrap());
        s.adaptive = false;
        let uniform_volume = signed_volume(&s.closed_mesh(&NoMeshResolver).unwrap());
        assert!(
            (adaptive_volume - uniform_volume).abs() < 0.1 * 2.0 * tol * 80.0,
            "{adaptive_volume} {uniform_volume}"
        );
    }
}

#[test]
fn seams_close_on_a_torus_and_a_sphere() {
    let torus = FormulaSurface::new(
        Some("(2 + 0.5*cos(v))*cos(u)"),
        Some("(2 + 0.5*cos(v))*sin(u)"),
        "0.5*sin(v)",
        [0.0, 2.0 * PI],
        [0.0, 2.0 * PI],
    )
    .unwrap();
    let sphere = FormulaSurface::new(
        Some("cos(u)*cos(v)"),
        Some("sin(u)*cos(v)"),
        "sin(v)",
        [0.0, 2.0 * PI],
        [-PI / 2.0, PI / 2.0],
    )
    .unwrap();
    for (surface, exact) in [
        (torus, 2.0 * PI * PI * 2.0 * 0.25),
        (sphere, 4.0 / 3.0 * PI),
    ] {
        let s = adaptive(SurfaceKind::Formula(surface), Closure::Closed, 1e-3);
        let sheet = s.sheet(&NoMeshResolver).unwrap();
        assert!(sheet.estimated);
        assert!(boundary_edges(&sheet.mesh).is_empty(), "{exact}");
        let v = signed_volume(&s.closed_mesh(&NoMeshResolver).unwrap());
        assert!(v < exact && exact - v < 0.01 * exact, "{v} {exact}");
    }
}

#[test]
fn a_tube_closes_its_seam_and_keeps_its_rims_open() {
    let tube = FormulaSurface::new(
        Some("cos(u)"),
        Some("sin(u)"),
        "v",
        [0.0, 2.0 * PI],
        [0.0, 1.0],
    )
    .unwrap();
    let s = adaptive(SurfaceKind::Formula(tube), slab(0.05), 1e-3);
    let sheet = s.sheet(&NoMeshResolver).unwrap();
    // Only the two rims are open: every boundary edge lies at z = 0 or z = 1.
    for (a, b) in boundary_edges(&sheet.mesh) {
        for p in [
            sheet.mesh.positions[a as usize],
            sheet.mesh.positions[b as usize],
        ] {
            assert!(
                p.z.abs() < 1e-12 || (p.z - 1.0).abs() < 1e-12,
                "seam left open at {p}"
            );
        }
    }
}
