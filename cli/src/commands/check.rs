//! `solidkit check`: read a mesh, report its topology, exit 1 unless it bounds a solid (closed
//! oriented manifold, no self-intersection).

use crate::args::CheckArgs;
use crate::output::{out, outln};
use crate::report;
use anyhow::Result;
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::{ReportOptions, TopologyReport};

/// Prints the report; exit code 0 for a closed oriented 2-manifold without self-intersections,
/// 1 otherwise.
pub fn run(a: &CheckArgs) -> Result<u8> {
    let mesh = read_mesh(&a.mesh)?;
    let options = ReportOptions {
        self_intersections: !a.no_self_intersections,
    };
    let r = TopologyReport::with_options(&mesh, &options);
    if a.json {
        outln!("{}", report::to_json(&r, &[])?)?;
    } else {
        out!("{}", r.to_text())?;
    }
    Ok(if r.is_valid_solid() { 0 } else { 1 })
}
