//! Adaptive subdivision: flat regions stay coarse while curved ones are refined, the result is
//! crack-free and manifold (closed where the input was), a vanishing tolerance is uniform
//! subdivision, and bad requests are refused.

use glam::DVec3;
use solidkit_kernel::polyhedra::PlatonicKind;
use std::collections::HashMap;

use super::tests::{mesh, platonic, triangle_grid};
use super::{Limits, Scheme, SubdivisionError, subdivide, subdivide_adaptive};
use crate::HalfEdgeMesh;

/// The surface of the cube `[0, n]³` made of unit quads, wound outwards (closed, χ = 2).
fn box_surface(n: i32) -> HalfEdgeMesh {
    let mut ids: HashMap<[i32; 3], u32> = HashMap::new();
    let mut positions = Vec::new();
    let mut quads = Vec::new();
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        for side in [0, n] {
            for i in 0..n {
                for j in 0..n {
                    let mut quad: Vec<u32> = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                        .iter()
                        .map(|&(u, v)| {
                            let mut p = [0; 3];
                            (p[a], p[b], p[c]) = (side, u, v);
                            *ids.entry(p).or_insert_with(|| {
                                positions.push(DVec3::new(
                                    f64::from(p[0]),
                                    f64::from(p[1]),
                                    f64::from(p[2]),
                                ));
                                (positions.len() - 1) as u32
                            })
                        })
                        .collect();
                    // e_b × e_c = e_a: as listed the quad faces +a; reversed on the low side.
                    if side == 0 {
                        quad.reverse();
                    }
                    quads.push(quad);
                }
            }
        }
    }
    mesh(positions, &quads)
}

fn euler(m: &HalfEdgeMesh) -> i64 {
    m.vertex_count() as i64 - m.edge_count() as i64 + m.face_count() as i64
}

#[test]
fn catmull_clark_keeps_the_flat_middles_of_a_box_coarse() {
    let input = box_surface(6);
    assert_eq!((input.face_count(), euler(&input)), (216, 2));
    let (m, levels) =
        subdivide_adaptive(&input, Scheme::CatmullClark, 1, 1e-6, &Limits::default()).unwrap();
    assert_eq!(m.validate(), Ok(()));
    assert!(m.is_closed());
    assert_eq!(euler(&m), 2);
    // Only the quads touching a cube edge move off their plane: 20 of the 36 per side. The ring
    // of 12 inside them gains the edge points of their split edges; the middle 2 × 2 stay.
    let l = levels[0];
    assert_eq!(
        (l.refined, l.closure_refined, l.conformed, l.kept),
        (6 * 20, 0, 6 * 12, 6 * 4),
        "{l:?}"
    );
    assert_eq!(l.faces_out, 6 * 20 * 4 + 6 * 16);
    assert_eq!(m.face_count(), l.faces_out);
    // The kept and conformed faces lie in the cube's faces; the rounding is at its edges.
    let p = m.positions();
    let on_face = |q: DVec3| q.to_array().iter().any(|&x| x == 0.0 || x == 6.0);
    let flat = m
        .face_ids()
        .filter(|&f| m.face_vertices(f).all(|v| on_face(p[v.index()])))
        .count();
    assert!(flat >= 6 * 16, "{flat}");
    // More levels: still closed and manifold. The limit surface is curved over the whole band
    // of width 1 along the cube's edges (its B-spline patches there use control points of the
    // neighbouring sides), so that band is refined at every level, and the middle stays as it
    // was: 120·4^k + 96 faces after k levels, against 216·4^k for uniform subdivision.
    let (deep, levels) =
        subdivide_adaptive(&input, Scheme::CatmullClark, 3, 1e-3, &Limits::default()).unwrap();
    assert_eq!(deep.validate(), Ok(()));
    assert!(deep.is_closed() && euler(&deep) == 2);
    for (k, l) in levels.iter().enumerate() {
        assert_eq!((l.conformed, l.kept), (72, 24), "level {}: {l:?}", k + 1);
    }
    assert_eq!(deep.face_count(), 120 * 64 + 96);
    let uniform = subdivide(&input, Scheme::CatmullClark, 3, &Limits::default()).unwrap();
    assert_eq!(uniform.face_count(), 216 * 64);
}

#[test]
fn loop_refines_the_curved_half_of_a_sheet_and_closes_red_green() {
    // Flat for x ≤ 4, a parabolic trough beyond.
    let input = triangle_grid(8, |x, _| {
        if x > 4.0 {
            0.25 * (x - 4.0).powi(2)
        } else {
            0.0
        }
    });
    let (m, levels) =
        subdivide_adaptive(&input, Scheme::Loop, 1, 1e-6, &Limits::default()).unwrap();
    assert_eq!(m.validate(), Ok(()));
    assert_eq!(m.boundary_loop_count(), 1);
    assert_eq!(euler(&m), 1);
    assert!(m.face_ids().all(|f| m.face_half_edges(f).count() == 3));
    let l = levels[0];
    assert!(l.conformed > 0, "green triangles along the border: {l:?}");
    let p = m.positions();
    let centroid_x = |f| m.face_vertices(f).map(|v| p[v.index()].x).sum::<f64>() / 3.0;
    let count = |keep: &dyn Fn(f64) -> bool| m.face_ids().filter(|&f| keep(centroid_x(f))).count();
    // The flat columns x < 2 keep their 2 × 2 × 8 triangles; the curved ones x > 5 are split
    // 1-to-4 (3 columns × 8 rows × 2 triangles × 4).
    assert_eq!(count(&|x| x < 2.0), 32);
    assert_eq!(count(&|x| x > 5.0), 192);
    // The flat part did not move.
    for f in m.face_ids().filter(|&f| centroid_x(f) < 3.0) {
        assert!(m.face_vertices(f).all(|v| p[v.index()].z == 0.0));
    }
}

#[test]
fn a_vanishing_tolerance_is_uniform_subdivision() {
    let ico = platonic(PlatonicKind::Icosahedron);
    let (a, levels) = subdivide_adaptive(&ico, Scheme::Loop, 2, 1e-12, &Limits::default()).unwrap();
    let b = subdivide(&ico, Scheme::Loop, 2, &Limits::default()).unwrap();
    assert_eq!(levels.len(), 2);
    assert!(levels.iter().all(|l| l.refined == l.faces_in));
    assert_eq!(a.positions(), b.positions());
    let faces = |m: &HalfEdgeMesh| -> Vec<Vec<u32>> {
        m.face_ids()
            .map(|f| m.face_vertices(f).map(|v| v.0).collect())
            .collect()
    };
    assert_eq!(faces(&a), faces(&b));
    // A tolerance above every deviation changes nothing and stops after one level.
    let (same, levels) =
        subdivide_adaptive(&ico, Scheme::CatmullClark, 5, 10.0, &Limits::default()).unwrap();
    assert_eq!((levels.len(), levels[0].refined), (1, 0));
    assert_eq!(same.face_count(), 20);
}

#[test]
fn bad_requests_are_refused() {
    let ico = platonic(PlatonicKind::Icosahedron);
    let cube = box_surface(1);
    let limits = Limits::default();
    assert!(matches!(
        subdivide_adaptive(&ico, Scheme::Butterfly, 1, 0.1, &limits),
        Err(SubdivisionError::NotAdaptive { .. })
    ));
    for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            subdivide_adaptive(&ico, Scheme::Loop, 1, t, &limits),
            Err(SubdivisionError::Tolerance(_))
        ));
    }
    assert!(matches!(
        subdivide_adaptive(&cube, Scheme::Loop, 1, 0.1, &limits),
        Err(SubdivisionError::NotTriangles { .. })
    ));
    assert!(matches!(
        subdivide_adaptive(
            &cube,
            Scheme::CatmullClark,
            3,
            1e-9,
            &Limits { max_faces: 100 }
        ),
        Err(SubdivisionError::TooLarge { level: 3, .. })
    ));
}
