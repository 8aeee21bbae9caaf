//! The sparse path against the dense reference: identical meshes on a set of models, identical
//! output for any thread count, cancellation, and evidence that culling happens.

use super::*;
use crate::TopologyReport;
use glam::DVec3;
use solidkit_kernel::Solid;

fn models() -> Vec<(&'static str, Solid)> {
    let bracket = Solid::difference_all(
        Solid::union_all([
            Solid::cuboid(DVec3::new(2.0, 1.2, 0.2)),
            Solid::cuboid(DVec3::new(0.2, 1.2, 1.4)).translate(DVec3::new(-0.9, 0.0, 0.6)),
        ]),
        [Solid::cylinder(0.12, 0.5).translate(DVec3::new(0.6, 0.3, 0.0))],
    );
    let mut beads = Solid::sphere(0.05);
    for i in 0..60 {
        let t = i as f64 * 0.2;
        beads = beads.union(
            &Solid::sphere(0.05 + 0.001 * i as f64).translate(DVec3::new(
                t.cos(),
                t.sin(),
                0.02 * t,
            )),
        );
    }
    vec![
        ("sphere", Solid::sphere(0.6)),
        (
            "torus",
            Solid::torus(1.0, 0.3).rotate(DVec3::new(1.0, 1.0, 0.0), 30.0),
        ),
        (
            "sphere-minus-cube",
            Solid::sphere(1.0).difference(&Solid::cube(1.2)),
        ),
        ("bracket", bracket),
        ("beads", beads),
        (
            "ellipsoid",
            Solid::sphere(1.0).scale(DVec3::new(1.0, 0.5, 0.25)),
        ),
        // Tips whose neighbouring samples are exact zeros: joined faces.
        (
            "tetrahedron",
            Solid::platonic(
                solidkit_kernel::polyhedra::PlatonicKind::Tetrahedron,
                solidkit_kernel::polyhedra::PlatonicSize::Circumradius(1.0),
            ),
        ),
        // A sheet thinner than a cell: many ambiguous faces, and tunnel loops with centre vertices.
        ("gyroid-sphere", solidkit_kernel::models::gyroid_sphere()),
    ]
}

fn spec(s: &Solid, resolution: usize) -> crate::marching_cubes::GridSpec {
    crate::marching_cubes::GridSpec::for_bounds(&s.bbox(), resolution).unwrap()
}

#[test]
fn sparse_equals_dense_bit_for_bit() {
    let (mut evaluated, mut total) = (0u64, 0u64);
    let (mut joined, mut centres) = (0, 0);
    for (name, solid) in models() {
        let p = solid.compile();
        for res in [37, 64] {
            let g = spec(&solid, res);
            let (j, c) = crate::marching_cubes::tests::joined_and_centre_cells(
                &SampleGrid::sample_program(&p, g),
            );
            (joined, centres) = (joined + j, centres + c);
            let dense = mesh_dense(&p, g);
            let (sparse, stats) = mesh_sparse(&p, g, &SparseOptions::default()).unwrap();
            assert!(!dense.triangles.is_empty(), "{name}");
            assert_eq!(
                sparse.positions.len(),
                dense.positions.len(),
                "{name} at {res}: vertices"
            );
            assert_eq!(sparse, dense, "{name} at {res}");
            if res == 64 {
                evaluated += stats.samples_evaluated;
                total += g.sample_count() as u64;
            }
            let r = TopologyReport::of(&sparse);
            assert!(r.is_closed_manifold(), "{name}: {r:?}");
        }
    }
    assert!(
        evaluated < total,
        "culling: {evaluated} of {total} samples evaluated"
    );
    // The decider's joined faces and centre vertices were exercised on both paths.
    assert!(
        joined > 0 && centres > 0,
        "joined {joined}, centres {centres}"
    );
}

/// Faces on sample planes, many on brick boundaries (8 cells per unit, bricks of 8 cells): the
/// lone zeros on them are settled from lattice neighbours, across bricks by the full program,
/// exactly as the dense grid settles them; so are the shared faces of the stack and the flush
/// cutter's faces.
#[test]
fn lattice_faces_on_brick_boundaries_mesh_as_dense() {
    let unit = |x: f64, y: f64, z: f64| Solid::cube(1.0).translate(DVec3::new(x, y, z) + 0.5);
    let stack = unit(0.0, 0.0, 0.0)
        .union(&unit(1.0, 0.0, 0.0))
        .union(&unit(1.0, 1.0, 0.0))
        .union(&unit(0.0, 0.0, 1.0))
        .difference(&Solid::cylinder(0.3, 2.0).translate(DVec3::new(0.5, 0.5, 1.0)));
    let p = stack.compile();
    for shift in [0.0, 1.0 / 64.0] {
        let g = crate::marching_cubes::GridSpec {
            origin: DVec3::splat(-1.0 + shift),
            cell: 0.125,
            cells: [32, 32, 32],
        };
        let grid = crate::marching_cubes::SampleGrid::sample_program(&p, g);
        let zeros = grid
            .values
            .iter()
            .filter(|v| v.abs() == f32::MIN_POSITIVE)
            .count();
        assert_eq!(zeros > 1000, shift == 0.0, "{zeros} zeros at shift {shift}");
        let dense = mesh_dense(&p, g);
        for brick_cells in [4, 8] {
            let opts = SparseOptions {
                brick_cells,
                ..Default::default()
            };
            assert_eq!(
                mesh_sparse(&p, g, &opts).unwrap().0,
                dense,
                "brick {brick_cells}"
            );
        }
        let report = TopologyReport::of(&dense);
        assert!(report.closed && report.manifold && report.oriented);
        assert_eq!((report.shells, report.genus), (1, Some(1)));
        // Exact volume: four unit cubes less the hole through two of them. Faces on sample
        // planes are not bevelled, so only the hole's facets differ (0.3%); off the lattice
        // marching cubes bevels every edge by up to a cell (3% at 8 cells per unit).
        let exact = 4.0 - std::f64::consts::PI * 0.09 * 2.0;
        let bound = if shift == 0.0 { 0.01 } else { 0.05 };
        let err = (report.volume - exact).abs() / exact;
        assert!(err < bound, "{} vs {exact} at shift {shift}", report.volume);
    }
}

#[test]
fn brick_size_does_not_change_the_mesh() {
    let (_, solid) = &models()[2];
    let p = solid.compile();
    let g = spec(solid, 50);
    let reference = mesh_dense(&p, g);
    for brick_cells in [1, 2, 4] {
        let opts = SparseOptions {
            brick_cells,
            ..Default::default()
        };
        assert_eq!(
            mesh_sparse(&p, g, &opts).unwrap().0,
            reference,
            "brick {brick_cells}"
        );
    }
}

#[test]
fn thread_count_does_not_change_the_mesh() {
    let (_, solid) = &models()[4];
    let p = solid.compile();
    let g = spec(solid, 96);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| mesh_sparse(&p, g, &SparseOptions::default()).unwrap().0)
    };
    assert_eq!(run(1), run(3));
}

/// A sink numbering its vertices downwards from 10⁹ − 1: the assembly must map every corner.
#[derive(Default)]
struct Backwards {
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
}

impl crate::sink::MeshSink for Backwards {
    fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        1_000_000_000 - self.positions.len() as u32
    }

    fn add_triangle(&mut self, t: [u32; 3]) {
        self.triangles.push(t);
    }
}

#[test]
fn a_sink_with_its_own_numbers_gets_the_same_mesh() {
    let (_, solid) = &models()[7];
    let p = solid.compile();
    let g = spec(solid, 48);
    let (mesh, _) = mesh_sparse(&p, g, &SparseOptions::default()).unwrap();
    let mut other = Backwards::default();
    mesh_sparse_into(&p, g, &SparseOptions::default(), &mut other).unwrap();
    assert_eq!(other.positions, mesh.positions);
    let renumbered: Vec<[u32; 3]> = other
        .triangles
        .iter()
        .map(|t| t.map(|v| 1_000_000_000 - 1 - v))
        .collect();
    assert!(!mesh.triangles.is_empty());
    assert_eq!(renumbered, mesh.triangles);
}

#[test]
fn surface_cost_not_volume() {
    let s = Solid::sphere(0.6);
    let p = s.compile();
    let b = solidkit_kernel::Aabb::centered(DVec3::ONE);
    let g64 = crate::marching_cubes::GridSpec::for_bounds(&b, 64).unwrap();
    let g128 = crate::marching_cubes::GridSpec::for_bounds(&b, 128).unwrap();
    let s64 = mesh_sparse(&p, g64, &SparseOptions::default()).unwrap().1;
    let s128 = mesh_sparse(&p, g128, &SparseOptions::default()).unwrap().1;
    // Doubling the resolution multiplies evaluated samples by about 4 (surface), not 8 (volume).
    let ratio = s128.samples_evaluated as f64 / s64.samples_evaluated as f64;
    assert!(ratio < 5.0, "ratio {ratio}");
}

#[test]
fn cancellation_stops_meshing() {
    let s = Solid::sphere(0.6);
    let p = s.compile();
    let g = spec(&s, 64);
    let token = CancelToken::new();
    token.cancel();
    let opts = SparseOptions {
        cancel: Some(token),
        ..Default::default()
    };
    assert_eq!(mesh_sparse(&p, g, &opts).unwrap_err(), Cancelled);
}

#[test]
fn progress_reaches_the_total() {
    use std::sync::{Arc, Mutex};
    let s = Solid::torus(1.0, 0.3);
    let p = s.compile();
    let seen = Arc::new(Mutex::new(Vec::new()));
    let sink = seen.clone();
    let opts = SparseOptions {
        progress: Some(Arc::new(move |pr: Progress| sink.lock().unwrap().push(pr))),
        ..Default::default()
    };
    let (_, stats) = mesh_sparse(&p, spec(&s, 48), &opts).unwrap();
    let seen = seen.lock().unwrap();
    let bricks: Vec<_> = seen.iter().filter(|p| p.stage == "bricks").collect();
    assert_eq!(bricks.len(), stats.surface_bricks);
    assert!(bricks.iter().any(|p| p.done == p.total));
}

/// The assembly works per brick layer (same `z` brick coordinate): layers without bricks between
/// and around the surfaces, a last layer cut short, one layer only, and any thread count.
#[test]
fn empty_and_partial_brick_layers_mesh_as_dense() {
    let apart = Solid::sphere(0.5)
        .translate(DVec3::new(0.0, 0.0, -2.0))
        .union(&Solid::sphere(0.4).translate(DVec3::new(0.3, 0.0, 2.0)));
    let p = apart.compile();
    for res in [45, 83] {
        let g = spec(&apart, res);
        let dense = mesh_dense(&p, g);
        for threads in [1, 3] {
            let sparse = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| mesh_sparse(&p, g, &SparseOptions::default()).unwrap().0);
            assert_eq!(sparse, dense, "at {res} on {threads} threads");
        }
        let r = TopologyReport::of(&dense);
        assert!(r.is_closed_manifold() && r.shells == 2, "{r:?}");
    }
    // A slab thinner than one brick along z: a single layer.
    let slab = Solid::cuboid(DVec3::new(2.0, 2.0, 0.1));
    let p = slab.compile();
    let mut g = spec(&slab, 40);
    g.cells[2] = g.cells[2].min(5);
    g.origin.z = -2.5 * g.cell;
    let dense = mesh_dense(&p, g);
    assert!(!dense.triangles.is_empty());
    assert_eq!(
        mesh_sparse(&p, g, &SparseOptions::default()).unwrap().0,
        dense
    );
    // A grid whose far z face cuts through the solid: crossing edges in the last sample plane,
    // which the last layer owns.
    let ball = Solid::sphere(1.0);
    let p = ball.compile();
    for res in [40, 48] {
        let mut g = spec(&ball, res);
        g.cells[2] = g.cells[2] * 2 / 3;
        let dense = mesh_dense(&p, g);
        let top = g.origin.z + g.cells[2] as f64 * g.cell;
        assert!(
            dense.positions.iter().any(|v| (v.z - top).abs() < 1e-6),
            "at {res}"
        );
        assert_eq!(
            mesh_sparse(&p, g, &SparseOptions::default()).unwrap().0,
            dense,
            "at {res}"
        );
    }
}
