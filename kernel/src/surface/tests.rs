//! Surface evaluation, closing and curvature against exact values.

use super::close::{boundary_edges, signed_volume};
use super::*;
use crate::patch::{BezierPatch, HeightDerivatives, monge_curvature, pn_triangle};
use crate::primitive::NoMeshResolver;
use glam::DVec3;

fn spec(kind: SurfaceKind, closure: Closure) -> SurfaceSpec {
    SurfaceSpec {
        kind,
        closure,
        tolerance: None,
        segments: None,
        adaptive: false,
    }
}

/// A closed mesh's edges each used once in each direction.
fn closed_oriented(m: &IndexedMesh) -> bool {
    let mut count = std::collections::HashMap::new();
    for t in &m.triangles {
        for c in 0..3 {
            *count.entry((t[c], t[(c + 1) % 3])).or_insert(0) += 1;
        }
    }
    count
        .iter()
        .all(|(&(a, b), &n)| n == 1 && count.get(&(b, a)) == Some(&1))
}

use crate::IndexedMesh;

fn flat_bilinear(w: f64, h: f64) -> TensorSurface {
    let pts = vec![
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(w, 0.0, 1.0),
        DVec3::new(0.0, h, 1.0),
        DVec3::new(w, h, 1.0),
    ];
    TensorSurface::bezier([2, 2], pts).unwrap()
}

#[test]
fn flat_patch_with_thickness_has_volume_area_times_thickness() {
    for side in [Side::Both, Side::Front, Side::Back] {
        let s = spec(
            SurfaceKind::Bezier(flat_bilinear(2.0, 3.0)),
            Closure::Thickness {
                thickness: 0.25,
                side,
            },
        );
        let m = s.closed_mesh(&NoMeshResolver).unwrap();
        assert!(closed_oriented(&m), "{side:?}");
        assert!((signed_volume(&m) - 6.0 * 0.25).abs() < 1e-12, "{side:?}");
    }
    let based = spec(
        SurfaceKind::Bezier(flat_bilinear(2.0, 3.0)),
        Closure::Base { z: -0.5 },
    );
    let m = based.closed_mesh(&NoMeshResolver).unwrap();
    assert!(closed_oriented(&m));
    assert!((signed_volume(&m) - 6.0 * 1.5).abs() < 1e-12);
    // An open sheet needs a closure; a base above the sheet is refused.
    let open = spec(
        SurfaceKind::Bezier(flat_bilinear(1.0, 1.0)),
        Closure::Closed,
    );
    assert!(open.closed_mesh(&NoMeshResolver).is_err());
    let above = spec(
        SurfaceKind::Bezier(flat_bilinear(1.0, 1.0)),
        Closure::Base { z: 2.0 },
    );
    assert_eq!(
        above.closed_mesh(&NoMeshResolver).unwrap_err().key(),
        "base"
    );
}

#[test]
fn bezier_tensor_matches_the_bezier_patch_and_its_derivatives() {
    let pts: Vec<DVec3> = (0..3)
        .flat_map(|j| {
            (0..4).map(move |i| DVec3::new(i as f64, j as f64, ((i * 7 + j * 3) % 5) as f64 * 0.3))
        })
        .collect();
    let t = TensorSurface::bezier([4, 3], pts.clone()).unwrap();
    let b = BezierPatch::new(3, 2, pts).unwrap();
    let h = 1e-5;
    for &(u, v) in &[(0.0, 0.0), (0.3, 0.7), (1.0, 0.5), (0.9, 1.0)] {
        let d = t.derivatives(u, v);
        assert!((d.p - b.point(u, v)).length() < 1e-12);
        assert!((d.pu - b.du(u, v)).length() < 1e-11);
        assert!((d.pv - b.dv(u, v)).length() < 1e-11);
        let (uc, vc) = (u.clamp(h, 1.0 - h), v.clamp(h, 1.0 - h));
        let c = t.derivatives(uc, vc);
        let fuu = (t.derivatives(uc + h, vc).pu - t.derivatives(uc - h, vc).pu) / (2.0 * h);
        let fuv = (t.derivatives(uc, vc + h).pu - t.derivatives(uc, vc - h).pu) / (2.0 * h);
        let fvv = (t.derivatives(uc, vc + h).pv - t.derivatives(uc, vc - h).pv) / (2.0 * h);
        assert!((c.puu - fuu).length() < 1e-6, "{:?} {fuu:?}", c.puu);
        assert!((c.puv - fuv).length() < 1e-6);
        assert!((c.pvv - fvv).length() < 1e-6);
    }
    // The control-net bound holds at samples.
    let [muu, muv, mvv] = t.second_derivative_bounds().unwrap();
    for i in 0..=20 {
        for j in 0..=20 {
            let d = t.derivatives(i as f64 / 20.0, j as f64 / 20.0);
            assert!(d.puu.length() <= muu + 1e-9 && d.puv.length() <= muv + 1e-9);
            assert!(d.pvv.length() <= mvv + 1e-9);
        }
    }
}

/// A quarter cylinder of radius 1 and height 2 as a NURBS surface (degree 2 × 1).
fn quarter_cylinder() -> TensorSurface {
    let w = std::f64::consts::FRAC_1_SQRT_2;
    let arc = [
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
    ];
    let mut pts = arc.to_vec();
    pts.extend(arc.iter().map(|p| *p + DVec3::Z * 2.0));
    TensorSurface::new(
        [2, 1],
        [3, 2],
        pts,
        Some(vec![1.0, w, 1.0, 1.0, w, 1.0]),
        [clamped_knots(2, 3), clamped_knots(1, 2)],
    )
    .unwrap()
}

#[test]
fn nurbs_quarter_cylinder_is_exact_and_its_curvature_is_that_of_a_cylinder() {
    let s = quarter_cylinder();
    for i in 0..=10 {
        for j in 0..=4 {
            let d = s.derivatives(i as f64 / 10.0, j as f64 / 4.0);
            assert!((d.p.truncate().length() - 1.0).abs() < 1e-14, "{:?}", d.p);
            let c = d.curvature();
            // Normal p_u × p_v points inwards (u turns counter-clockwise, v goes up).
            assert!(c.gaussian.abs() < 1e-12, "{c:?}");
            assert!((c.mean.abs() - 0.5).abs() < 1e-12, "{c:?}");
        }
    }
    // A thick shell of the quarter cylinder: the annulus sector's volume, within the chord error.
    let t = 0.2;
    let sp = SurfaceSpec {
        kind: SurfaceKind::Nurbs(s),
        closure: Closure::Thickness {
            thickness: t,
            side: Side::Both,
        },
        tolerance: Some(1e-5),
        segments: None,
        adaptive: false,
    };
    let m = sp.closed_mesh(&NoMeshResolver).unwrap();
    assert!(closed_oriented(&m));
    let exact = std::f64::consts::FRAC_PI_4 * (1.1f64.powi(2) - 0.9f64.powi(2)) * 2.0;
    let v = signed_volume(&m);
    assert!((v - exact).abs() < 1e-4 * exact, "{v} {exact}");
}

/// `h = sin(uv)` and its derivatives.
fn sin_uv(u: f64, v: f64) -> HeightDerivatives {
    let (s, c) = (u * v).sin_cos();
    HeightDerivatives {
        h: s,
        hx: v * c,
        hy: u * c,
        hxx: -v * v * s,
        hxy: c - u * v * s,
        hyy: -u * u * s,
    }
}

#[test]
fn formula_graph_sin_uv_curvature_matches_the_closed_forms() {
    // The notes' z = sin(uv) as a graph; both forms (z only, and x, y, z) agree.
    let graph = FormulaSurface::new(None, None, "sin(u*v)", [-2.0, 2.0], [-2.0, 2.0]).unwrap();
    let full =
        FormulaSurface::new(Some("u"), Some("v"), "sin(u*v)", [-2.0, 2.0], [-2.0, 2.0]).unwrap();
    for &(u, v) in &[
        (0.0, 0.0),
        (1.62, 1.12),
        (-1.18, -0.8),
        (0.5, -1.9),
        (2.0, 2.0),
    ] {
        let exact = monge_curvature(&sin_uv(u, v));
        for f in [&graph, &full] {
            let d = f.derivatives_at(u, v);
            assert!((d.p.z - (u * v).sin()).abs() < 1e-15);
            let c = d.curvature();
            assert!(
                (c.gaussian - exact.gaussian).abs() < 1e-12,
                "{c:?} {exact:?}"
            );
            assert!((c.mean - exact.mean).abs() < 1e-12, "{c:?} {exact:?}");
        }
    }
    // The notes' parametric form x = v, y = sin(uv)/2, z = u: a graph y = sin(zx)/2, so its
    // Gaussian curvature is that of h(z, x) = sin(zx)/2 (the sign of H follows the normal).
    let notes =
        FormulaSurface::new(Some("v"), Some("sin(u*v)/2"), "u", [-2.0, 2.0], [-2.0, 2.0]).unwrap();
    for &(u, v) in &[(1.62, 1.12), (-1.18, -0.8)] {
        let d = sin_uv(u, v);
        let half = HeightDerivatives {
            h: d.h / 2.0,
            hx: d.hx / 2.0,
            hy: d.hy / 2.0,
            hxx: d.hxx / 2.0,
            hxy: d.hxy / 2.0,
            hyy: d.hyy / 2.0,
        };
        let exact = monge_curvature(&half);
        let c = notes.derivatives_at(u, v).curvature();
        assert!((c.gaussian - exact.gaussian).abs() < 1e-12);
        assert!((c.mean.abs() - exact.mean.abs()).abs() < 1e-12);
    }
}

#[test]
fn formula_sphere_welds_into_a_closed_solid() {
    let f = FormulaSurface::new(
        Some("cos(u)*cos(v)"),
        Some("sin(u)*cos(v)"),
        "sin(v)",
        [0.0, 2.0 * std::f64::consts::PI],
        [-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2],
    )
    .unwrap();
    let mut s = spec(SurfaceKind::Formula(f), Closure::Closed);
    s.tolerance = Some(1e-4);
    let sheet = s.sheet(&NoMeshResolver).unwrap();
    assert!(boundary_edges(&sheet.mesh).is_empty());
    let m = s.closed_mesh(&NoMeshResolver).unwrap();
    assert!(closed_oriented(&m));
    let v = signed_volume(&m);
    let exact = 4.0 / 3.0 * std::f64::consts::PI;
    // Inscribed: below the ball by at most area × chord error (estimated).
    let chord = sheet.chord_error.unwrap();
    assert!(
        v < exact && exact - v < 4.0 * std::f64::consts::PI * chord * 1.5,
        "{v} {chord}"
    );
}

#[test]
fn pn_control_points_follow_the_notes() {
    let p = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.2),
        DVec3::new(0.1, 1.0, -0.1),
    ];
    let n = [
        DVec3::new(0.1, -0.2, 1.0).normalize(),
        DVec3::new(0.3, 0.0, 1.0).normalize(),
        DVec3::new(-0.2, 0.4, 1.0).normalize(),
    ];
    let w = |i: usize, j: usize| (p[j] - p[i]).dot(n[i]);
    let b210 = (2.0 * p[0] + p[1] - w(0, 1) * n[0]) / 3.0;
    let b120 = (2.0 * p[1] + p[0] - w(1, 0) * n[1]) / 3.0;
    let b021 = (2.0 * p[1] + p[2] - w(1, 2) * n[1]) / 3.0;
    let b012 = (2.0 * p[2] + p[1] - w(2, 1) * n[2]) / 3.0;
    let b102 = (2.0 * p[2] + p[0] - w(2, 0) * n[2]) / 3.0;
    let b201 = (2.0 * p[0] + p[2] - w(0, 2) * n[0]) / 3.0;
    let e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    let v = (p[0] + p[1] + p[2]) / 3.0;
    let b111 = e + (e - v) / 2.0;
    let t = pn_triangle(p, n).unwrap();
    // control(j, k) is b_{3−j−k, j, k}.
    let expected = [
        ((0, 0), p[0]),
        ((3, 0), p[1]),
        ((0, 3), p[2]),
        ((1, 0), b210),
        ((2, 0), b120),
        ((2, 1), b021),
        ((1, 2), b012),
        ((0, 2), b102),
        ((0, 1), b201),
        ((1, 1), b111),
    ];
    for ((j, k), b) in expected {
        assert!((t.control(j, k) - b).length() < 1e-15, "b at {j},{k}");
    }
}

#[test]
fn pn_octahedron_closes_itself_and_grows_towards_the_sphere() {
    let v = vec![
        DVec3::X,
        DVec3::NEG_X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::Z,
        DVec3::NEG_Z,
    ];
    let t = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    let s = spec(
        SurfaceKind::Pn(PnSource::Inline {
            vertices: v.clone(),
            normals: Some(v),
            triangles: t,
        }),
        Closure::Closed,
    );
    let m = s.closed_mesh(&NoMeshResolver).unwrap();
    assert!(closed_oriented(&m));
    let vol = signed_volume(&m);
    // Between the octahedron (4/3) and the ball (4π/3).
    assert!(
        vol > 4.0 / 3.0 + 0.5 && vol < 4.0 / 3.0 * std::f64::consts::PI,
        "{vol}"
    );
}

#[test]
fn bezier_triangle_with_thickness_is_a_closed_slab() {
    // A flat degree-2 triangle: area 1/2, so a slab of 0.1 has volume 0.05.
    let t = crate::patch::TriangleBezier::from_fn(2, |i, j, _| {
        DVec3::new(j as f64 / 2.0, (2 - i - j) as f64 / 2.0, 0.0)
    })
    .unwrap();
    let s = spec(
        SurfaceKind::Triangle(t),
        Closure::Thickness {
            thickness: 0.1,
            side: Side::Front,
        },
    );
    let m = s.closed_mesh(&NoMeshResolver).unwrap();
    assert!(closed_oriented(&m));
    assert!((signed_volume(&m) - 0.05).abs() < 1e-12);
}
