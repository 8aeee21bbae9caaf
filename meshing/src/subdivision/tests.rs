//! Tests of the subdivision schemes: counts and Euler characteristic at every level, closedness,
//! boundary loops, convergence, interpolation, polynomial reproduction, and the errors.

use glam::DVec3;
use solidkit_kernel::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron};

use super::{Counts, Limits, Scheme, SubdivisionError, subdivide};
use crate::HalfEdgeMesh;
use crate::topology::test_meshes::{cube_positions, cube_quads, octahedron, torus, torus_quads};

/// Builds and validates a polygon mesh.
pub(super) fn mesh(positions: Vec<DVec3>, faces: &[Vec<u32>]) -> HalfEdgeMesh {
    let m = HalfEdgeMesh::from_polygons(positions, faces).expect("valid test mesh");
    assert_eq!(m.validate(), Ok(()));
    m
}

pub(super) fn cube() -> HalfEdgeMesh {
    mesh(cube_positions(), &cube_quads())
}

pub(super) fn platonic(kind: PlatonicKind) -> HalfEdgeMesh {
    let p = Polyhedron::platonic(kind, PlatonicSize::Circumradius(1.0)).expect("platonic");
    mesh(p.vertices().to_vec(), p.faces())
}

fn torus_of_quads() -> HalfEdgeMesh {
    let (positions, quads) = torus_quads(12, 8);
    mesh(positions, &quads)
}

fn torus_of_triangles() -> HalfEdgeMesh {
    let t = torus(12, 8);
    HalfEdgeMesh::from_indexed(&t).expect("torus")
}

/// An `n × n` grid of unit quads in the plane z = 0 (open, one boundary loop).
pub(super) fn quad_grid(n: u32) -> HalfEdgeMesh {
    let (positions, quads) = grid(n, |_, _| 0.0);
    mesh(positions, &quads)
}

/// An `n × n` grid of unit squares, each split by the same diagonal (interior valence 6), with
/// heights `z(x, y)`.
pub(super) fn triangle_grid(n: u32, z: impl Fn(f64, f64) -> f64) -> HalfEdgeMesh {
    let (positions, quads) = grid(n, z);
    let triangles: Vec<Vec<u32>> = quads
        .iter()
        .flat_map(|q| [vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]])
        .collect();
    mesh(positions, &triangles)
}

pub(super) fn grid(n: u32, z: impl Fn(f64, f64) -> f64) -> (Vec<DVec3>, Vec<Vec<u32>>) {
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut positions = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (f64::from(i), f64::from(j));
            positions.push(DVec3::new(x, y, z(x, y)));
        }
    }
    let mut quads = Vec::new();
    for j in 0..n {
        for i in 0..n {
            quads.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    (positions, quads)
}

/// One level of `scheme`, validated.
fn once(m: &HalfEdgeMesh, scheme: Scheme) -> HalfEdgeMesh {
    let next = subdivide(m, scheme, 1, &Limits::default()).expect("subdivides");
    assert_eq!(next.validate(), Ok(()), "{scheme}");
    next
}

/// Largest distance moved by the vertices both meshes share (the primal schemes keep the old
/// vertices first).
fn max_displacement(before: &HalfEdgeMesh, after: &HalfEdgeMesh) -> f64 {
    before
        .positions()
        .iter()
        .zip(after.positions())
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max)
}

fn sum_of_degrees(m: &HalfEdgeMesh) -> usize {
    m.face_ids().map(|f| m.face_half_edges(f).count()).sum()
}

#[test]
fn catmull_clark_cube_counts_closedness_and_convergence() {
    let mut m = cube();
    let mut displacements = Vec::new();
    for level in 1..=5 {
        let next = once(&m, Scheme::CatmullClark);
        let (v, e, f) = (m.vertex_count(), m.edge_count(), m.face_count());
        let degrees = sum_of_degrees(&m);
        assert_eq!(next.vertex_count(), v + e + f, "level {level}");
        assert_eq!(next.edge_count(), 2 * e + degrees, "level {level}");
        assert_eq!(next.face_count(), degrees, "level {level}");
        assert!(next.is_closed(), "level {level}");
        assert_eq!(next.euler_characteristic(), 2, "level {level}");
        assert!(
            next.face_ids()
                .all(|f| next.face_half_edges(f).count() == 4)
        );
        displacements.push(max_displacement(&m, &next));
        m = next;
    }
    // Geometric convergence: every level moves the vertices less than half as far as the last.
    for pair in displacements.windows(2).skip(1) {
        assert!(pair[1] <= 0.5 * pair[0], "{displacements:?}");
    }
    // The cube's symmetry is kept: centred at (1/2, 1/2, 1/2), inside the cube.
    let centre: DVec3 = m.positions().iter().sum::<DVec3>() / m.vertex_count() as f64;
    assert!(centre.distance(DVec3::splat(0.5)) < 1e-12);
    assert!(
        m.positions()
            .iter()
            .all(|p| p.min_element() > 0.0 && p.max_element() < 1.0)
    );
}

#[test]
fn loop_icosahedron_converges_to_a_round_surface() {
    let mut m = platonic(PlatonicKind::Icosahedron);
    let mut displacements = Vec::new();
    let mut spreads = vec![radial_spread(&m)];
    for level in 1..=5 {
        let next = once(&m, Scheme::Loop);
        assert_eq!(next.face_count(), 4 * m.face_count());
        assert_eq!(next.vertex_count(), m.vertex_count() + m.edge_count());
        assert!(next.is_closed() && next.is_triangle_mesh(), "level {level}");
        assert_eq!(next.euler_characteristic(), 2, "level {level}");
        displacements.push(max_displacement(&m, &next));
        spreads.push(radial_spread(&next));
        m = next;
    }
    for pair in displacements.windows(2) {
        assert!(pair[1] <= 0.5 * pair[0], "{displacements:?}");
    }
    // The spread of distances from the centre falls level by level (20 % for the icosahedron)
    // towards that of the limit surface, which is round to within 1.5 %.
    for pair in spreads.windows(2) {
        assert!(pair[1] < pair[0], "{spreads:?}");
    }
    assert!(spreads[0] > 0.2 && spreads[5] < 0.015, "{spreads:?}");
}

/// `(max − min) / max` of the distances from the origin of the vertices and face centroids (the
/// centroids stand for the faces, whose points are nearer the centre than the vertices).
fn radial_spread(m: &HalfEdgeMesh) -> f64 {
    let centroid = |f| {
        let (sum, n) = m
            .face_vertices(f)
            .fold((DVec3::ZERO, 0.0), |(s, n), v| (s + m.position(v), n + 1.0));
        sum / n
    };
    let radii = m
        .positions()
        .iter()
        .copied()
        .chain(m.face_ids().map(centroid))
        .map(DVec3::length);
    let (lo, hi) = radii.fold((f64::INFINITY, 0.0f64), |(lo, hi), r| {
        (lo.min(r), hi.max(r))
    });
    (hi - lo) / hi
}

/// The volume enclosed by a closed mesh (polygons fanned from their first vertex).
fn volume(m: &HalfEdgeMesh) -> f64 {
    crate::TopologyReport::of(&m.to_indexed()).volume
}

#[test]
fn butterfly_interpolates_and_stays_closed() {
    for start in [
        platonic(PlatonicKind::Icosahedron),
        HalfEdgeMesh::from_indexed(&octahedron()).expect("octahedron"),
        platonic(PlatonicKind::Tetrahedron),
    ] {
        let original: Vec<u64> = start
            .positions()
            .iter()
            .flat_map(|p| p.to_array().map(f64::to_bits))
            .collect();
        let mut m = start.clone();
        for level in 1..=4 {
            m = once(&m, Scheme::Butterfly);
            assert!(m.is_closed() && m.is_triangle_mesh(), "level {level}");
            assert_eq!(m.euler_characteristic(), 2, "level {level}");
            let kept: Vec<u64> = m.positions()[..start.vertex_count()]
                .iter()
                .flat_map(|p| p.to_array().map(f64::to_bits))
                .collect();
            assert_eq!(kept, original, "level {level}: original vertices moved");
        }
    }
}

#[test]
fn butterfly_reproduces_cubics_on_a_regular_grid() {
    let cubic = |x: f64, y: f64| 0.01 * (x * x * x - 2.0 * x * y * y + 3.0 * y * y) + 0.1 * x - y;
    let n = 8;
    let m = triangle_grid(n, cubic);
    let next = once(&m, Scheme::Butterfly);
    let mut checked = 0;
    // Edge vertices whose full eight-point stencil lies well inside the grid are on the cubic.
    for p in &next.positions()[m.vertex_count()..] {
        let inside = |t: f64| (2.0..=f64::from(n) - 2.0).contains(&t);
        if inside(p.x) && inside(p.y) {
            assert!((p.z - cubic(p.x, p.y)).abs() < 1e-12, "{p}");
            checked += 1;
        }
    }
    assert!(checked > 50, "{checked}");
}

#[test]
fn flat_grids_stay_flat() {
    for scheme in Scheme::ALL {
        let m = if scheme.needs_triangles() {
            triangle_grid(4, |x, y| 0.5 * x - 0.25 * y)
        } else {
            let (positions, quads) = grid(4, |x, y| 0.5 * x - 0.25 * y);
            mesh(positions, &quads)
        };
        let next = subdivide(&m, scheme, 2, &Limits::default()).expect("subdivides");
        for p in next.positions() {
            assert!(
                (p.z - (0.5 * p.x - 0.25 * p.y)).abs() < 1e-12,
                "{scheme}: {p}"
            );
        }
    }
}

#[test]
fn doo_sabin_cube_counts_and_closedness() {
    let mut m = cube();
    let mut volumes = vec![volume(&m)];
    for level in 1..=5 {
        let next = once(&m, Scheme::DooSabin);
        let (v, e, f) = (m.vertex_count(), m.edge_count(), m.face_count());
        assert_eq!(next.face_count(), f + e + v, "level {level}");
        assert_eq!(next.vertex_count(), sum_of_degrees(&m), "level {level}");
        assert_eq!(next.edge_count(), 2 * sum_of_degrees(&m), "level {level}");
        assert!(next.is_closed(), "level {level}");
        assert_eq!(next.euler_characteristic(), 2, "level {level}");
        volumes.push(volume(&next));
        m = next;
    }
    // Convergence: each level cuts less volume than half what the previous one cut.
    let cuts: Vec<f64> = volumes.windows(2).map(|w| w[0] - w[1]).collect();
    for pair in cuts.windows(2) {
        assert!(pair[1] > 0.0 && pair[1] <= 0.5 * pair[0], "{volumes:?}");
    }
}

#[test]
fn genus_one_keeps_euler_characteristic_zero() {
    for scheme in Scheme::ALL {
        let start = if scheme.needs_triangles() {
            torus_of_triangles()
        } else {
            torus_of_quads()
        };
        let mut m = start;
        for level in 1..=3 {
            m = once(&m, scheme);
            assert!(m.is_closed(), "{scheme} level {level}");
            assert_eq!(m.euler_characteristic(), 0, "{scheme} level {level}");
        }
    }
    // The polygon schemes on the triangle torus too.
    for scheme in [Scheme::CatmullClark, Scheme::DooSabin] {
        let m = subdivide(&torus_of_triangles(), scheme, 2, &Limits::default()).expect("ok");
        assert!(m.is_closed());
        assert_eq!(m.euler_characteristic(), 0, "{scheme}");
    }
}

#[test]
fn open_grid_keeps_one_boundary_loop() {
    for scheme in Scheme::ALL {
        let mut m = if scheme.needs_triangles() {
            triangle_grid(4, |_, _| 0.0)
        } else {
            quad_grid(4)
        };
        for level in 1..=3 {
            m = once(&m, scheme);
            assert_eq!(m.boundary_loop_count(), 1, "{scheme} level {level}");
            assert_eq!(m.euler_characteristic(), 1, "{scheme} level {level}");
            assert!(!m.is_closed());
        }
    }
}

#[test]
fn predicted_counts_match() {
    let closed = [
        cube(),
        platonic(PlatonicKind::Icosahedron),
        platonic(PlatonicKind::Dodecahedron),
        torus_of_quads(),
        torus_of_triangles(),
    ];
    for start in closed
        .iter()
        .chain([&quad_grid(3), &triangle_grid(3, |_, _| 0.0)])
    {
        for scheme in Scheme::ALL {
            if scheme.needs_triangles() && !start.is_triangle_mesh() {
                continue;
            }
            let predicted = Counts::of(start).next(scheme).next(scheme);
            let actual = Counts::of(&subdivide(start, scheme, 2, &Limits::default()).unwrap());
            assert_eq!(predicted, actual, "{scheme}");
        }
    }
}

#[test]
fn loop_and_butterfly_refuse_polygons() {
    for scheme in [Scheme::Loop, Scheme::Butterfly] {
        let err = subdivide(&cube(), scheme, 1, &Limits::default()).unwrap_err();
        assert_eq!(
            err,
            SubdivisionError::NotTriangles {
                scheme,
                face: 0,
                corners: 4
            }
        );
        assert!(err.to_string().contains("needs a triangle mesh"), "{err}");
    }
}

#[test]
fn sizes_over_the_limit_are_refused_before_any_work() {
    let limits = Limits { max_faces: 100 };
    // 24, 96, 384 faces: the third level is over.
    assert!(subdivide(&cube(), Scheme::CatmullClark, 2, &limits).is_ok());
    let err = subdivide(&cube(), Scheme::CatmullClark, 3, &limits).unwrap_err();
    assert_eq!(
        err,
        SubdivisionError::TooLarge {
            scheme: Scheme::CatmullClark,
            levels: 3,
            level: 3,
            faces: 384,
            limit: 100
        }
    );
    // The default limit stops absurd requests at once (u32::MAX levels).
    let err = subdivide(&cube(), Scheme::DooSabin, u32::MAX, &Limits::default()).unwrap_err();
    assert!(
        matches!(err, SubdivisionError::TooLarge { level, .. } if level < 20),
        "{err}"
    );
    // Zero levels is a copy.
    let m = cube();
    assert_eq!(
        subdivide(&m, Scheme::Loop, 0, &limits),
        Err(SubdivisionError::NotTriangles {
            scheme: Scheme::Loop,
            face: 0,
            corners: 4
        })
    );
    assert_eq!(subdivide(&m, Scheme::CatmullClark, 0, &limits).unwrap(), m);
}

/// V, E, F of `m`.
fn vef(m: &HalfEdgeMesh) -> [usize; 3] {
    [m.vertex_count(), m.edge_count(), m.face_count()]
}

/// The textbook counts after one level, from V, E, F, the sum of face degrees `Σ` and the
/// boundary edges `E_b` (0 when closed):
/// Catmull-Clark `V + E + F`, `2E + Σ`, `Σ`; Loop `V + E`, `2E + 3F`, `4F`;
/// Doo-Sabin (with the boundary rule) `Σ + 2E_b`, `Σ + 2E + 2E_b`, `F + E + V`.
fn closed_form(
    scheme: Scheme,
    [v, e, f]: [usize; 3],
    degrees: usize,
    boundary: usize,
) -> [usize; 3] {
    match scheme {
        Scheme::CatmullClark => [v + e + f, 2 * e + degrees, degrees],
        Scheme::Loop | Scheme::Butterfly => [v + e, 2 * e + 3 * f, 4 * f],
        Scheme::DooSabin => [
            degrees + 2 * boundary,
            degrees + 2 * e + 2 * boundary,
            f + e + v,
        ],
    }
}

fn boundary_edges(m: &HalfEdgeMesh) -> usize {
    m.half_edge_ids()
        .filter(|&h| m.is_boundary_half_edge(h))
        .count()
}

#[test]
fn counts_after_one_and_two_levels_match_the_closed_forms_with_and_without_boundary() {
    // A closed cube, an open 3 × 3 quad grid (V 16, E 24, F 9, 12 boundary edges), an open cube
    // (the top face removed), an open triangle grid and a closed octahedron.
    let open_cube = {
        let mut quads = cube_quads();
        quads.remove(1);
        mesh(cube_positions(), &quads)
    };
    let starts = [
        (cube(), false),
        (quad_grid(3), true),
        (open_cube, true),
        (triangle_grid(3, |_, _| 0.0), true),
        (
            HalfEdgeMesh::from_indexed(&octahedron()).expect("octahedron"),
            false,
        ),
    ];
    for (start, open) in &starts {
        assert_eq!(boundary_edges(start) > 0, *open);
        for scheme in [Scheme::CatmullClark, Scheme::Loop, Scheme::DooSabin] {
            if scheme.needs_triangles() && !start.is_triangle_mesh() {
                continue;
            }
            let mut m = start.clone();
            for level in 1..=2 {
                let expected = closed_form(scheme, vef(&m), sum_of_degrees(&m), boundary_edges(&m));
                let next = once(&m, scheme);
                assert_eq!(vef(&next), expected, "{scheme} level {level}, open {open}");
                assert_eq!(next.euler_characteristic(), start.euler_characteristic());
                assert_eq!(next.boundary_loop_count(), start.boundary_loop_count());
                m = next;
            }
        }
    }
    // The 3 × 3 grid's numbers written out: Catmull-Clark gives the 6 × 6 grid (49, 84, 36) and
    // then the 12 × 12 grid; Doo-Sabin gives Σ + 2E_b = 36 + 24 vertices.
    let grid = quad_grid(3);
    assert_eq!(vef(&grid), [16, 24, 9]);
    let cc = once(&grid, Scheme::CatmullClark);
    assert_eq!(vef(&cc), [49, 84, 36]);
    assert_eq!(vef(&once(&cc, Scheme::CatmullClark)), [169, 312, 144]);
    assert_eq!(vef(&once(&grid, Scheme::DooSabin)), [60, 108, 49]);
}

/// The smallest box around the positions used by faces.
fn extent(m: &HalfEdgeMesh) -> (DVec3, DVec3) {
    let mut lo = DVec3::splat(f64::INFINITY);
    let mut hi = DVec3::splat(f64::NEG_INFINITY);
    for f in m.face_ids() {
        for v in m.face_vertices(f) {
            lo = lo.min(m.position(v));
            hi = hi.max(m.position(v));
        }
    }
    (lo, hi)
}

#[test]
fn open_meshes_do_not_shrink_from_their_boundary() {
    // A flat 4 × 4 sheet: with the boundary rules every scheme keeps the sheet's square outline
    // (the boundary is a spline of the boundary polygon, whose sides are straight), and keeps the
    // midpoints of the old boundary edges on the new boundary.
    for scheme in [Scheme::CatmullClark, Scheme::Loop, Scheme::DooSabin] {
        let start = if scheme.needs_triangles() {
            triangle_grid(4, |_, _| 0.0)
        } else {
            quad_grid(4)
        };
        let mut m = start.clone();
        for level in 1..=3 {
            m = once(&m, scheme);
            let (lo, hi) = extent(&m);
            assert!(
                lo.distance(DVec3::ZERO) < 1e-12,
                "{scheme} level {level}: {lo}"
            );
            assert!(
                hi.distance(DVec3::new(4.0, 4.0, 0.0)) < 1e-12,
                "{scheme} level {level}: {hi}"
            );
        }
        let once = once(&start, scheme);
        let on_boundary = |q: DVec3| {
            once.half_edge_ids()
                .filter(|&h| once.is_boundary_half_edge(h))
                .any(|h| {
                    let (a, b) = once.edge_vertices(h);
                    let (a, b) = (once.position(a), once.position(b));
                    // q on the segment ab.
                    (q - a).cross(b - a).length() < 1e-12
                        && (q - a).dot(b - a) >= -1e-12
                        && (q - b).dot(a - b) >= -1e-12
                })
        };
        for h in start
            .half_edge_ids()
            .filter(|&h| start.is_boundary_half_edge(h))
        {
            let (a, b) = start.edge_vertices(h);
            let mid = 0.5 * (start.position(a) + start.position(b));
            assert!(on_boundary(mid), "{scheme}: {mid}");
        }
    }
    // Doo-Sabin on a bent open surface (the cube without its top): the rim stays the square of
    // the old rim's edge midpoints cut at the corners, at the old rim's height.
    let mut quads = cube_quads();
    quads.remove(1);
    let open_cube = mesh(cube_positions(), &quads);
    let next = once(&open_cube, Scheme::DooSabin);
    let top = extent(&open_cube).1.z;
    for h in next
        .half_edge_ids()
        .filter(|&h| next.is_boundary_half_edge(h))
    {
        let p = next.position(next.half_edge(h).origin);
        assert!((p.z - top).abs() < 1e-12, "{p}");
    }
}
