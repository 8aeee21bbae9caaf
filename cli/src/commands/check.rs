//! `solidkit check`: read a mesh, report its topology, exit 1 unless it bounds a solid.

use crate::args::CheckArgs;
use crate::report;
use anyhow::Result;
use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::read_mesh;

/// Prints the report; exit code 0 for a closed oriented 2-manifold, 1 otherwise.
pub fn run(a: &CheckArgs) -> Result<u8> {
    let mesh = read_mesh(&a.mesh)?;
    let r = TopologyReport::of(&mesh);
    if a.json {
        println!("{}", report::to_json(&r, &[])?);
    } else {
        print!("{}", r.to_text());
    }
    Ok(if r.is_closed_manifold() { 0 } else { 1 })
}
