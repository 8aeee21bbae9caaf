//! Criterion benchmarks of the kernel's triangle BVH on one thread, over the marching-cubes mesh
//! of `gyroid-sphere` at 128³ (about 550 000 triangles): the build with one and four triangles per
//! leaf (the mesh solid's and the measures' trees), nearest-point queries from the surface samples
//! of a dual-contouring mesh of the same model at 112³ (the Hausdorff pattern: queries on or very
//! near the surface) and from a 48³ lattice over the model's domain (the mesh solid's field
//! pattern), and the self-intersection count of the mesh (box-overlap queries).
//! Run with `cargo bench -p solidkit-meshing --bench bvh`.

use criterion::{BenchmarkId, Criterion, Throughput};
use glam::DVec3;
use solidkit_kernel::bvh::TriangleBvh;
use solidkit_kernel::models::Model;
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::intersect::self_intersections;
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::measure::SurfaceSamples;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use std::hint::black_box;

/// Lattice points along each axis of the domain for the volume queries.
const LATTICE: usize = 48;

fn bvh(c: &mut Criterion) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("thread pool");
    let model = Model::by_name("gyroid-sphere").expect("model");
    let program = model.solid.compile();
    let grid = |n| GridSpec::covering(&model.domain, n).expect("grid");
    let (mesh, _) = mesh_sparse(&program, grid(128), &SparseOptions::default()).expect("mesh");
    let (other, _) = mesh_dc(&program, grid(112), &DcOptions::default()).expect("mesh");
    let samples = SurfaceSamples::of(&other, 100_000);
    let surface: Vec<DVec3> = samples
        .vertices
        .iter()
        .chain(&samples.area)
        .copied()
        .collect();
    let (lo, hi) = (model.domain.min, model.domain.max);
    let volume: Vec<DVec3> = (0..LATTICE.pow(3))
        .map(|i| {
            let (x, y, z) = (i % LATTICE, i / LATTICE % LATTICE, i / LATTICE / LATTICE);
            let t = DVec3::new(x as f64, y as f64, z as f64) + 0.5;
            lo + (hi - lo) * t / LATTICE as f64
        })
        .collect();
    let triangles: Vec<[DVec3; 3]> = (0..mesh.triangles.len())
        .map(|t| mesh.triangle_positions(t))
        .collect();

    let mut group = c.benchmark_group("bvh_build_1_thread");
    group.sample_size(10);
    group.throughput(Throughput::Elements(triangles.len() as u64));
    for leaf in [1, 4] {
        group.bench_with_input(BenchmarkId::from_parameter(leaf), &leaf, |b, &leaf| {
            b.iter(|| {
                pool.install(|| black_box(TriangleBvh::new(triangles.clone(), leaf).expect("bvh")))
            });
        });
    }
    group.finish();

    let mut group = c.benchmark_group("bvh_nearest_1_thread");
    group.sample_size(10);
    for leaf in [1, 4] {
        let tree = TriangleBvh::new(triangles.clone(), leaf).expect("bvh");
        for (name, queries) in [("surface", &surface), ("volume", &volume)] {
            group.throughput(Throughput::Elements(queries.len() as u64));
            let id = BenchmarkId::new(name, format!("leaf {leaf}"));
            group.bench_with_input(id, queries, |b, queries| {
                b.iter(|| {
                    let sum: f64 = queries
                        .iter()
                        .map(|&q| tree.nearest(q).map_or(0.0, |n| n.distance2))
                        .sum();
                    black_box(sum)
                });
            });
        }
    }
    group.finish();

    let mut group = c.benchmark_group("self_intersections_1_thread");
    group.sample_size(10);
    group.bench_function("gyroid-sphere 128", |b| {
        b.iter(|| pool.install(|| black_box(self_intersections(&mesh, 10).expect("finite"))));
    });
    group.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bvh(&mut c);
    c.final_summary();
}
