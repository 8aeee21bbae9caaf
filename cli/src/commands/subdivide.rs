//! `solidkit subdivide`: polygon mesh file → half-edge mesh → subdivision → file and report.

use crate::args::SubdivideArgs;
use crate::output::{out, outln};
use crate::report;
use anyhow::{Result, anyhow};
use serde_json::json;
use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::{PolygonMesh, read_polygon_mesh, write_polygon_mesh};
use solidkit_meshing::subdivision::{Limits, Scheme, subdivide};
use std::time::Instant;

/// Subdivides, writes the result and prints its report (of the triangulated faces); exit code 0.
pub fn run(a: &SubdivideArgs) -> Result<u8> {
    let name = a.mesh.display();
    let input = read_polygon_mesh(&a.mesh)?;
    let mesh = input
        .to_half_edge()
        .map_err(|e| anyhow!("{name}: cannot subdivide: {e}"))?;
    let scheme = Scheme::from(a.scheme);
    // The face limit is also the memory budget: the result, its polygons, their triangles and the
    // report take about `BYTES_PER_FACE` per face at the peak (a cube to 1.6 M faces: 1.45 GB), so
    // a request that would not fit in half of the machine's memory is refused before any work
    // rather than aborting after writing gigabytes.
    let memory = total_memory();
    let budget_faces = memory / 2 / BYTES_PER_FACE;
    let limits = Limits {
        max_faces: a.max_faces.min(budget_faces),
    };
    let start = Instant::now();
    let result = subdivide(&mesh, scheme, a.levels, &limits).map_err(|e| {
        if budget_faces < a.max_faces {
            anyhow!(
                "{name}: {e} (the memory budget: about {} KiB per face, half of this machine's {} MiB)",
                BYTES_PER_FACE / 1024,
                memory >> 20
            )
        } else {
            anyhow!("{name}: {e}")
        }
    })?;
    let time_s = start.elapsed().as_secs_f64();
    let polygons = PolygonMesh::from_half_edge(&result);
    write_polygon_mesh(&a.output, &polygons)?;
    let r = TopologyReport::of(&polygons.triangulated());
    let largest = polygons.faces.iter().map(Vec::len).max().unwrap_or(0);
    if a.json {
        let extra = [
            ("scheme", json!(scheme.name())),
            ("levels", json!(a.levels)),
            ("polygon_vertices", json!(result.vertex_count())),
            ("polygon_edges", json!(result.edge_count())),
            ("polygon_faces", json!(result.face_count())),
            ("largest_face", json!(largest)),
            ("time_s", json!(time_s)),
        ];
        outln!("{}", report::to_json(&r, &extra)?)?;
    } else {
        outln!("scheme: {scheme}, {} level(s)", a.levels)?;
        outln!(
            "polygon mesh: {} vertices, {} edges, {} faces (largest {largest} corners)",
            result.vertex_count(),
            result.edge_count(),
            result.face_count()
        )?;
        outln!("report of its triangles:")?;
        out!("{}", r.to_text())?;
        outln!("time: {time_s:.3} s")?;
        outln!("wrote: {}", a.output.display())?;
    }
    Ok(0)
}

/// Peak memory per output face of `subdivide` (measured: about 925 bytes), rounded up.
const BYTES_PER_FACE: u64 = 1024;

/// The machine's memory in bytes (`MemTotal` of `/proc/meminfo`), or 8 GiB where unknown.
fn total_memory() -> u64 {
    let known = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
            let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
            kib.checked_mul(1024)
        });
    known.unwrap_or(8 << 30)
}
