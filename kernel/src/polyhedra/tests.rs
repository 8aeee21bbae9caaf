//! Tests of the exact polyhedra: counts against the textbook values, Euler's formula, volumes in
//! closed form, duality, prisms with holes and every error path.

use super::*;
use glam::{DVec2, DVec3};

fn platonic(kind: PlatonicKind, size: PlatonicSize) -> Polyhedron {
    Polyhedron::platonic(kind, size).unwrap()
}

/// Closed-form volume for edge `a`.
fn volume_for_edge(kind: PlatonicKind, a: f64) -> f64 {
    let s5 = 5f64.sqrt();
    a.powi(3)
        * match kind {
            PlatonicKind::Tetrahedron => 1.0 / (6.0 * 2f64.sqrt()),
            PlatonicKind::Cube => 1.0,
            PlatonicKind::Octahedron => 2f64.sqrt() / 3.0,
            PlatonicKind::Dodecahedron => (15.0 + 7.0 * s5) / 4.0,
            PlatonicKind::Icosahedron => 5.0 * (3.0 + s5) / 12.0,
        }
}

#[test]
fn platonic_counts_match_the_notes() {
    let expected = [
        (4, 6, 4),
        (8, 12, 6),
        (6, 12, 8),
        (20, 30, 12),
        (12, 30, 20),
    ];
    for (kind, (v, e, f)) in PlatonicKind::ALL.into_iter().zip(expected) {
        let p = platonic(kind, PlatonicSize::Circumradius(1.0));
        assert_eq!(
            (p.vertex_count(), p.edge_count(), p.face_count()),
            (v, e, f),
            "{kind:?}"
        );
        assert_eq!(p.euler_characteristic(), 2);
        p.check_closed().unwrap();
        let mut sides: Vec<usize> = p.faces().iter().map(Vec::len).collect();
        sides.dedup();
        assert_eq!(sides.len(), 1, "{kind:?} faces are all alike");
    }
}

#[test]
fn platonic_sizes_and_volumes_are_exact() {
    for kind in PlatonicKind::ALL {
        let p = platonic(kind, PlatonicSize::Edge(1.5));
        let v = p.vertices();
        for f in p.faces() {
            for (i, &a) in f.iter().enumerate() {
                let b = f[(i + 1) % f.len()];
                let len = v[a as usize].distance(v[b as usize]);
                assert!((len - 1.5).abs() < 1e-12, "{kind:?} edge {len}");
            }
        }
        let exact = volume_for_edge(kind, 1.5);
        assert!((p.volume() - exact).abs() < 1e-12 * exact, "{kind:?}");
        let q = platonic(kind, PlatonicSize::Circumradius(2.0));
        assert!(
            q.vertices()
                .iter()
                .all(|v| (v.length() - 2.0).abs() < 1e-12)
        );
    }
}

/// Vertices divided by the largest distance from the origin, sorted.
fn normalised(p: &Polyhedron) -> Vec<DVec3> {
    let r = p.vertices().iter().map(|v| v.length()).fold(0.0, f64::max);
    let mut v: Vec<DVec3> = p.vertices().iter().map(|v| *v / r).collect();
    v.sort_by(|a, b| a.to_array().partial_cmp(&b.to_array()).unwrap());
    v
}

#[test]
fn duals_pair_up_and_dual_of_dual_is_the_original() {
    for kind in PlatonicKind::ALL {
        let p = platonic(kind, PlatonicSize::Circumradius(1.3));
        let d = p.dual().unwrap();
        let other = platonic(kind.dual(), PlatonicSize::Circumradius(1.0));
        assert_eq!(
            (d.vertex_count(), d.edge_count(), d.face_count()),
            (other.vertex_count(), other.edge_count(), other.face_count()),
            "{kind:?}"
        );
        assert_eq!(d.euler_characteristic(), 2);
        assert!(d.volume() > 0.0, "{kind:?} dual faces outward");
        // The dual is regular: all edges equal, all vertices on a sphere.
        let r0 = d.vertices()[0].length();
        assert!(d.vertices().iter().all(|v| (v.length() - r0).abs() < 1e-12));
        let dd = d.dual().unwrap();
        let (a, b) = (normalised(&p), normalised(&dd));
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            assert!(x.distance(*y) < 1e-12, "{kind:?}: {x} vs {y}");
        }
        // Vertex i of the dual of the dual lies on the ray of vertex i.
        for (x, y) in p.vertices().iter().zip(dd.vertices()) {
            assert!(x.normalize().distance(y.normalize()) < 1e-12);
        }
        let rotated = |faces: &[Vec<u32>]| -> Vec<Vec<u32>> {
            faces
                .iter()
                .map(|f| {
                    let k = f
                        .iter()
                        .enumerate()
                        .min_by_key(|(_, v)| **v)
                        .map_or(0, |(k, _)| k);
                    [&f[k..], &f[..k]].concat()
                })
                .collect()
        };
        assert_eq!(
            rotated(dd.faces()),
            rotated(p.faces()),
            "{kind:?} faces come back"
        );
    }
}

#[test]
fn dual_needs_a_closed_convex_polyhedron() {
    let cube = platonic(PlatonicKind::Cube, PlatonicSize::Edge(2.0));
    let open = Polyhedron::new(cube.vertices().to_vec(), cube.faces()[1..].to_vec()).unwrap();
    assert!(matches!(open.dual(), Err(PolyhedronError::OpenEdge { .. })));
    // Push one cube vertex inwards: faces through it stay valid polygons but the solid is not
    // convex any more.
    let mut v = cube.vertices().to_vec();
    v[0] *= 0.5;
    let dented = Polyhedron::new(v, cube.faces().to_vec());
    match dented {
        Ok(d) => assert!(matches!(d.dual(), Err(PolyhedronError::NotConvex { .. }))),
        Err(e) => assert!(matches!(e, PolyhedronError::BadFace { .. })),
    }
    let mut flipped = cube.faces().to_vec();
    flipped[0].reverse();
    let flipped = Polyhedron::new(cube.vertices().to_vec(), flipped).unwrap();
    assert!(matches!(
        flipped.check_closed(),
        Err(PolyhedronError::RepeatedEdge { .. })
    ));
}

fn square(c: DVec2, h: f64) -> Vec<DVec2> {
    [(-h, -h), (h, -h), (h, h), (-h, h)]
        .iter()
        .map(|&(x, y)| c + DVec2::new(x, y))
        .collect()
}

#[test]
fn prism_counts_volume_and_orientation() {
    // A heptagon prism as in the notes has 14 vertices.
    let heptagon: Vec<DVec2> = (0..7)
        .map(|i| {
            let a = f64::from(i) * std::f64::consts::TAU / 7.0;
            DVec2::new(a.cos(), a.sin())
        })
        .collect();
    let prism = Prism::new(heptagon, vec![], DVec3::new(0.3, 0.0, 2.0));
    let p = prism.to_polyhedron().unwrap();
    assert_eq!(
        (p.vertex_count(), p.edge_count(), p.face_count()),
        (14, 21, 9)
    );
    assert_eq!(p.euler_characteristic(), 2);
    p.check_closed().unwrap();
    assert!((p.volume() - prism.volume()).abs() < 1e-12);
    // Swept downwards with a clockwise polygon: still outward faces.
    let mut cw = square(DVec2::ZERO, 1.0);
    cw.reverse();
    let down = Prism::new(cw, vec![], DVec3::new(0.0, 0.0, -3.0));
    let p = down.to_polyhedron().unwrap();
    assert!((p.volume() - 12.0).abs() < 1e-12);
}

#[test]
fn prism_with_holes_has_genus_from_euler() {
    let holes = vec![
        square(DVec2::new(-1.0, 0.0), 0.4),
        square(DVec2::new(1.0, 0.0), 0.4),
    ];
    let prism = Prism::new(square(DVec2::ZERO, 2.0), holes, DVec3::Z);
    let p = prism.to_polyhedron().unwrap();
    p.check_closed().unwrap();
    assert_eq!(p.euler_characteristic(), 2 - 2 * 2);
    assert!((p.volume() - (16.0 - 2.0 * 0.64)).abs() < 1e-12);
    assert!((prism.volume() - p.volume()).abs() < 1e-12);
}

#[test]
fn bad_prisms_name_their_part() {
    let err = |p: Prism| p.to_polyhedron().unwrap_err();
    let flat = Prism::new(square(DVec2::ZERO, 1.0), vec![], DVec3::X);
    assert_eq!(err(flat), PolyhedronError::FlatDirection);
    let bow = [(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)].map(|(x, y)| DVec2::new(x, y));
    let e = err(Prism::new(bow.to_vec(), vec![], DVec3::Z));
    assert!(
        matches!(
            e,
            PolyhedronError::BadCrossSection {
                part: "polygon",
                ..
            }
        ),
        "{e}"
    );
    let outside = vec![square(DVec2::new(5.0, 0.0), 0.5)];
    let e = err(Prism::new(square(DVec2::ZERO, 1.0), outside, DVec3::Z));
    assert_eq!(
        e,
        PolyhedronError::BadCrossSection {
            part: "holes",
            problem: TriangulationError::HoleOutside
        }
    );
}

#[test]
fn invalid_polyhedra_are_errors() {
    let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    let new = |v: &[DVec3], f: Vec<Vec<u32>>| Polyhedron::new(v.to_vec(), f).unwrap_err();
    assert_eq!(new(&v, vec![]), PolyhedronError::NoFaces);
    assert!(matches!(
        new(&v, vec![vec![0, 1]]),
        PolyhedronError::TooFewCorners {
            face: 0,
            corners: 2
        }
    ));
    assert!(matches!(
        new(&v, vec![vec![0, 1, 2], vec![0, 1, 7]]),
        PolyhedronError::IndexOutOfRange {
            face: 1,
            index: 7,
            count: 4
        }
    ));
    assert!(matches!(
        new(&v, vec![vec![0, 1, 1]]),
        PolyhedronError::RepeatedCorner { face: 0, index: 1 }
    ));
    let mut nan = v.clone();
    nan[2].y = f64::NAN;
    assert_eq!(
        new(&nan, vec![vec![0, 1, 2]]),
        PolyhedronError::NonFiniteVertex { vertex: 2 }
    );
    let line = [DVec3::ZERO, DVec3::X, DVec3::X * 2.0, DVec3::X * 3.0];
    assert!(matches!(
        new(&line, vec![vec![0, 1, 2, 3]]),
        PolyhedronError::BadFace { face: 0, .. }
    ));
    assert!(matches!(
        Polyhedron::platonic(PlatonicKind::Cube, PlatonicSize::Edge(-1.0)),
        Err(PolyhedronError::InvalidSize { parameter: "edge" })
    ));
}

#[test]
fn non_manifold_vertex_is_reported() {
    // Two tetrahedra sharing only vertex 0.
    let v = vec![
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(-1.0, 0.0, 0.0),
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(0.0, 0.0, -1.0),
    ];
    let tet =
        |a: u32, b: u32, c: u32| vec![vec![0, b, a], vec![0, c, b], vec![0, a, c], vec![a, b, c]];
    let mut faces = tet(1, 2, 3);
    faces.extend(tet(4, 6, 5));
    let p = Polyhedron::new(v, faces).unwrap();
    assert_eq!(
        p.check_closed(),
        Err(PolyhedronError::NonManifoldVertex { vertex: 0 })
    );
}

#[test]
fn closed_forms_match_the_built_solids() {
    for kind in PlatonicKind::ALL {
        let m = kind.unit_measures();
        let p = platonic(kind, PlatonicSize::Edge(2.0));
        assert_eq!(
            [p.vertex_count(), p.edge_count(), p.face_count()],
            m.counts,
            "{kind:?}"
        );
        assert!(
            (p.volume() - 8.0 * m.volume).abs() < 1e-12 * m.volume,
            "{kind:?}"
        );
        assert!(
            (m.volume - volume_for_edge(kind, 1.0)).abs() < 1e-15,
            "{kind:?}"
        );
        let r = p.vertices().iter().map(|v| v.length()).fold(0.0, f64::max);
        assert!((r - 2.0 * m.circumradius).abs() < 1e-12, "{kind:?}");
        assert!(p.faces().iter().all(|f| f.len() == m.face_sides));
        let area: f64 = p
            .triangles()
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| p.vertices()[i as usize]);
                (b - a).cross(c - a).length() / 2.0
            })
            .sum();
        assert!((area - 4.0 * m.area).abs() < 1e-12 * m.area, "{kind:?}");
        // Volume = area · inradius / 3 (pyramids on the faces).
        assert!(
            (m.volume - m.area * m.inradius / 3.0).abs() < 1e-14,
            "{kind:?}"
        );
        let dual = p.dual().unwrap();
        let v = dual.vertices();
        let f = &dual.faces()[0];
        let edge = v[f[0] as usize].distance(v[f[1] as usize]);
        assert!(
            (edge - kind.dual_edge(2.0)).abs() < 1e-12,
            "{kind:?} dual edge {edge}"
        );
    }
}
