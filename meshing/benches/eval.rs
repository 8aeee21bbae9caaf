//! Criterion benchmarks of raw single-thread evaluation, no pruning: `Program::eval_many` on
//! `sphere` and `gyroid-sphere` (throughput in points), `Program::interval_with` on `sphere`
//! (throughput in boxes). Run with `cargo bench -p solidkit-meshing --bench eval`.

use criterion::{BenchmarkId, Criterion, Throughput};
use solidkit_kernel::models::Model;
use solidkit_kernel::models::workload::{lattice_points, octree_boxes};
use solidkit_kernel::program::{BatchScratch, IntervalScratch};
use std::hint::black_box;

/// Points per evaluation run (as `solidkit bench --raw`).
const POINTS: usize = 1 << 22;
/// Boxes per interval run.
const BOXES: usize = 1 << 16;

fn eval(c: &mut Criterion) {
    let mut group = c.benchmark_group("eval_many");
    group.sample_size(20);
    group.throughput(Throughput::Elements(POINTS as u64));
    for name in ["sphere", "gyroid-sphere"] {
        let model = Model::by_name(name).expect("model");
        let program = model.solid.compile();
        let pts = lattice_points(&model.domain, POINTS);
        let mut out = vec![0.0f32; POINTS];
        let mut scratch = BatchScratch::new(&program);
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| {
                program.eval_many(&pts.x, &pts.y, &pts.z, &mut out, &mut scratch);
                black_box(&mut out);
            });
        });
    }
    group.finish();
}

fn interval(c: &mut Criterion) {
    let mut group = c.benchmark_group("interval");
    group.throughput(Throughput::Elements(BOXES as u64));
    let model = Model::by_name("sphere").expect("model");
    let program = model.solid.compile();
    let boxes = octree_boxes(&model.domain, BOXES, 1);
    let mut scratch = IntervalScratch::default();
    group.bench_function(BenchmarkId::from_parameter("sphere"), |b| {
        b.iter(|| {
            for bx in &boxes {
                black_box(program.interval_with(black_box(bx), &mut scratch));
            }
        });
    });
    group.finish();
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    eval(&mut c);
    interval(&mut c);
    c.final_summary();
}
