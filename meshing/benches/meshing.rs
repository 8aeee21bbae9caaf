//! Criterion benchmarks of sparse meshing on one thread: `sphere` at 128³ and 256³ and
//! `gyroid-sphere` at 128³, over `GridSpec::covering(domain, n)` (the benchmark convention); dual
//! contouring of `sphere` at 256³ and `gyroid-sphere` at 128³.
//! Run with `cargo bench -p solidkit-meshing --bench meshing`.

use criterion::{BenchmarkId, Criterion};
use solidkit_kernel::models::Model;
use solidkit_meshing::dual_contouring::{DcOptions, mesh_dc};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use std::hint::black_box;

fn meshing(c: &mut Criterion) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("thread pool");
    let mut group = c.benchmark_group("mesh_sparse_1_thread");
    group.sample_size(10);
    for (name, n) in [("sphere", 128), ("sphere", 256), ("gyroid-sphere", 128)] {
        let model = Model::by_name(name).expect("model");
        let program = model.solid.compile();
        let spec = GridSpec::covering(&model.domain, n).expect("grid");
        let opts = SparseOptions::default();
        group.bench_with_input(BenchmarkId::new(name, n), &spec, |b, spec| {
            b.iter(|| {
                pool.install(|| black_box(mesh_sparse(&program, *spec, &opts).expect("mesh")))
            });
        });
    }
    group.finish();
    let mut group = c.benchmark_group("mesh_dc_1_thread");
    group.sample_size(10);
    for (name, n) in [("sphere", 256), ("gyroid-sphere", 128)] {
        let model = Model::by_name(name).expect("model");
        let program = model.solid.compile();
        let spec = GridSpec::covering(&model.domain, n).expect("grid");
        let opts = DcOptions::default();
        group.bench_with_input(BenchmarkId::new(name, n), &spec, |b, spec| {
            b.iter(|| pool.install(|| black_box(mesh_dc(&program, *spec, &opts).expect("mesh"))));
        });
    }
    group.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    meshing(&mut c);
    c.final_summary();
}
