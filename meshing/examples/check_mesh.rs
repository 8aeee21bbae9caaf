//! Check a mesh file: closed, 2-manifold, oriented, shells and genus, self-intersections.
//!
//! `cargo run --release -p solidkit-meshing --example check_mesh MESH.{stl,obj,off,ply,3mf,glb}`

use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::read_mesh;
use std::process::ExitCode;

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: check_mesh MESH");
        return ExitCode::from(2);
    };
    // Hostile files get a located error, never a panic.
    let mesh = match read_mesh(path.as_ref()) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let report = TopologyReport::of(&mesh);
    print!("{}", report.to_text());
    let sound = report.closed && report.manifold && report.self_intersections == Some(0);
    ExitCode::from(if sound { 0 } else { 1 })
}
