//! `peers`: solidkit against fidget 0.5.1 (VM and JIT), side by side in one run.
//!
//! Meshes `sphere` at 256³ and 128³ and `gyroid-sphere` at 128³ over `[-1, 1]³` with the same
//! thread count (1 by default) and prints the median of K runs of each mesher (interleaved, so
//! drift on a shared machine hits all three alike), the ratios fidget / solidkit, the triangle
//! counts and whether each mesh is a closed manifold. Build and run with `cargo run --release
//! -p solidkit-tests --features peers --bin peers -- [--repeat K] [--threads N]`.
//!
//! Timed: solidkit's `mesh_sparse` on `GridSpec::covering([-1, 1]³, n)` with the program
//! compiled beforehand; fidget's `Octree::build` (depth `log2 n`) and `walk_dual` with the shape
//! (VM tape or JIT code) built beforehand. The two methods differ (marching cubes on the grid
//! samples vs manifold dual contouring of the same octree depth); the grids are the same. The
//! `DC` rows time solidkit's dual contouring (`mesh_dc`) against the same fidget runs: the same
//! method on both sides.

mod fidget_side;
mod solidkit_side;

use solidkit_kernel::IndexedMesh;
use solidkit_meshing::TopologyReport;
use std::time::Instant;

/// One mesher's runs of one case.
struct Runs {
    times: Vec<f64>,
    mesh: IndexedMesh,
}

impl Runs {
    fn median(&self) -> f64 {
        let mut t = self.times.clone();
        t.sort_by(f64::total_cmp);
        let n = t.len();
        if n % 2 == 1 {
            t[n / 2]
        } else {
            0.5 * (t[n / 2 - 1] + t[n / 2])
        }
    }
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let out = f();
    (out, start.elapsed().as_secs_f64())
}

fn parse_args() -> Result<(usize, usize), String> {
    let (mut repeat, mut threads) = (5, 1);
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let value = args
            .next()
            .and_then(|v| v.parse::<usize>().ok())
            .filter(|v| *v >= 1);
        match (a.as_str(), value) {
            ("--repeat", Some(v)) => repeat = v,
            ("--threads", Some(v)) => threads = v,
            _ => {
                return Err(format!(
                    "usage: peers [--repeat K] [--threads N] (at '{a}')"
                ));
            }
        }
    }
    Ok((repeat, threads))
}

fn check(mesh: &IndexedMesh) -> String {
    let r = TopologyReport::of(mesh);
    let genus = r.genus.map_or("-".to_string(), |g| g.to_string());
    match (r.closed, r.manifold) {
        (true, true) => format!("closed manifold, genus {genus}"),
        _ => format!(
            "NOT closed manifold ({} boundary, {} non-manifold edges)",
            r.boundary_edges, r.non_manifold_edges
        ),
    }
}

fn main() -> std::process::ExitCode {
    let (repeat, threads) = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("{e}");
            return std::process::ExitCode::from(2);
        }
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    let fidget_pool = fidget_side::Pool::new(threads);
    println!("solidkit vs fidget 0.5.1: {threads} thread(s), median of {repeat} runs each\n");
    println!(
        "{:<14} {:>5} {:>11} {:>11} {:>11} {:>9} {:>9} {:>10} {:>10} {:>10}",
        "model",
        "grid",
        "solidkit s",
        "fidget VM s",
        "fidget JIT",
        "VM/sk",
        "JIT/sk",
        "tris sk",
        "tris VM",
        "tris JIT"
    );
    let mut notes = Vec::new();
    for (name, n) in [("sphere", 256), ("sphere", 128), ("gyroid-sphere", 128)] {
        let ours = solidkit_side::Case::new(name, n);
        let vm = fidget_side::Case::vm(name, n);
        let jit = fidget_side::Case::jit(name, n);
        let mut runs: [Runs; 4] = std::array::from_fn(|_| Runs {
            times: Vec::new(),
            mesh: IndexedMesh::default(),
        });
        for _ in 0..repeat {
            let (m, t) = timed(|| pool.install(|| ours.mesh()));
            runs[0].times.push(t);
            runs[0].mesh = m;
            let (m, t) = timed(|| vm.mesh(&fidget_pool));
            runs[1].times.push(t);
            runs[1].mesh = fidget_side::to_indexed(&m);
            let (m, t) = timed(|| jit.mesh(&fidget_pool));
            runs[2].times.push(t);
            runs[2].mesh = fidget_side::to_indexed(&m);
            let (m, t) = timed(|| pool.install(|| ours.mesh_dc()));
            runs[3].times.push(t);
            runs[3].mesh = m;
        }
        let [sk, v, j, dc] = [
            runs[0].median(),
            runs[1].median(),
            runs[2].median(),
            runs[3].median(),
        ];
        println!(
            "{:<14} {:>5} {:>11.4} {:>11.4} {:>11.4} {:>8.2}x {:>8.2}x {:>10} {:>10} {:>10}",
            name,
            format!("{n}³"),
            sk,
            v,
            j,
            v / sk,
            j / sk,
            runs[0].mesh.triangle_count(),
            runs[1].mesh.triangle_count(),
            runs[2].mesh.triangle_count()
        );
        println!(
            "{:<14} {:>5} {:>11.4} {:>11.4} {:>11.4} {:>8.2}x {:>8.2}x {:>10} {:>10} {:>10}",
            format!("{name} DC"),
            format!("{n}³"),
            dc,
            v,
            j,
            v / dc,
            j / dc,
            runs[3].mesh.triangle_count(),
            runs[1].mesh.triangle_count(),
            runs[2].mesh.triangle_count()
        );
        let names = ["solidkit", "fidget VM", "fidget JIT", "solidkit DC"];
        for (who, r) in names.iter().zip(&runs) {
            let (lo, hi) = r
                .times
                .iter()
                .fold((f64::MAX, 0.0f64), |(a, b), t| (a.min(*t), b.max(*t)));
            notes.push(format!(
                "{name} {n}³ {who}: min {lo:.4} s, max {hi:.4} s; {}",
                check(&r.mesh)
            ));
        }
    }
    println!();
    for n in notes {
        println!("{n}");
    }
    std::process::ExitCode::SUCCESS
}
