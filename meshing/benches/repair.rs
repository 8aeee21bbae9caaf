//! Criterion benchmarks of the minimal repair (`solidkit repair --mode minimal` without the
//! reading, reports and writing) on one and two threads, over the marching-cubes mesh of
//! `gyroid-sphere` at 128³ (about 1.3 million triangles in one large shell with a few hundred
//! small shells inside its bounding box: the nesting test casts one ray per small shell), as
//! meshed and with every 20th face flipped.
//! Run with `cargo bench -p solidkit-meshing --bench repair`.

use criterion::{BenchmarkId, Criterion, Throughput};
use solidkit_kernel::models::Model;
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use solidkit_meshing::repair::{MinimalOptions, repair_minimal};
use std::hint::black_box;

fn repair(c: &mut Criterion) {
    let model = Model::by_name("gyroid-sphere").expect("model");
    let program = model.solid.compile();
    let grid = GridSpec::covering(&model.domain, 128).expect("grid");
    let (clean, _) = mesh_sparse(&program, grid, &SparseOptions::default()).expect("mesh");
    let mut flipped = clean.clone();
    for t in flipped.triangles.iter_mut().step_by(20) {
        t.swap(1, 2);
    }
    let opts = MinimalOptions { weld: 1e-9 };
    let mut group = c.benchmark_group("repair minimal");
    group.sample_size(10);
    group.throughput(Throughput::Elements(clean.triangles.len() as u64));
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool");
        for (name, mesh) in [("clean", &clean), ("5% flipped", &flipped)] {
            let id = BenchmarkId::new(name, format!("{threads} threads"));
            group.bench_function(id, |b| {
                b.iter(|| pool.install(|| black_box(repair_minimal(mesh, &opts).expect("repair"))));
            });
        }
    }
    group.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    repair(&mut c);
    c.final_summary();
}
