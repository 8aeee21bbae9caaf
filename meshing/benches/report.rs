//! Criterion benchmarks of the topology report on one and two threads, over the marching-cubes
//! mesh of `gyroid-sphere` at 128³ (about 1.3 million triangles): the report without
//! self-intersections (counts, shells, genus, measures), the self-intersection test alone, and
//! the report as `solidkit mesh` gives it for a marching-cubes run (self-intersections known by
//! construction) and as `solidkit check` gives it (tested).
//! Run with `cargo bench -p solidkit-meshing --bench report`.

use criterion::{BenchmarkId, Criterion, Throughput};
use solidkit_kernel::models::Model;
use solidkit_meshing::intersect::self_intersections;
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use solidkit_meshing::{ReportOptions, TopologyReport};
use std::hint::black_box;

fn report(c: &mut Criterion) {
    let model = Model::by_name("gyroid-sphere").expect("model");
    let program = model.solid.compile();
    let grid = GridSpec::covering(&model.domain, 128).expect("grid");
    let (mesh, stats) = mesh_sparse(&program, grid, &SparseOptions::default()).expect("mesh");
    assert!(stats.intersection_free, "marching cubes certifies its mesh");
    let skip = ReportOptions {
        self_intersections: false,
    };
    let full = ReportOptions::default();
    let mut group = c.benchmark_group("report");
    group.sample_size(10);
    group.throughput(Throughput::Elements(mesh.triangles.len() as u64));
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool");
        let id = |name: &str| BenchmarkId::new(name, format!("{threads} threads"));
        group.bench_function(id("without self-intersections"), |b| {
            b.iter(|| pool.install(|| black_box(TopologyReport::with_options(&mesh, &skip))));
        });
        group.bench_function(id("self-intersections"), |b| {
            b.iter(|| pool.install(|| black_box(self_intersections(&mesh, 8).expect("finite"))));
        });
        group.bench_function(id("mesh (construction)"), |b| {
            b.iter(|| {
                pool.install(|| black_box(TopologyReport::with_certificate(&mesh, &full, true)))
            });
        });
        group.bench_function(id("check (tested)"), |b| {
            b.iter(|| pool.install(|| black_box(TopologyReport::with_options(&mesh, &full))));
        });
    }
    group.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    report(&mut c);
    c.final_summary();
}
