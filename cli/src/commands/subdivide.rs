//! `solidkit subdivide`: polygon mesh file → half-edge mesh → subdivision → file and report.

use crate::args::SubdivideArgs;
use crate::output::{out, outln};
use crate::report;
use anyhow::{Result, anyhow};
use serde_json::json;
use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::{PolygonMesh, read_polygon_mesh, write_polygon_mesh};
use solidkit_meshing::subdivision::{AdaptiveLevel, Limits, Scheme, subdivide, subdivide_adaptive};
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
    let run = match a.adaptive {
        None => subdivide(&mesh, scheme, a.levels, &limits).map(|m| (m, Vec::new())),
        Some(t) => subdivide_adaptive(&mesh, scheme, a.levels, t, &limits),
    };
    let (result, adaptive_levels) = run.map_err(|e| {
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
            ("adaptive", json!(a.adaptive)),
            ("adaptive_levels", adaptive_json(&adaptive_levels)),
            ("time_s", json!(time_s)),
        ];
        outln!("{}", report::to_json(&r, &extra)?)?;
    } else {
        match a.adaptive {
            None => outln!("scheme: {scheme}, {} level(s)", a.levels)?,
            Some(t) => {
                outln!(
                    "scheme: {scheme}, adaptive to {t}, {} of at most {} level(s)",
                    adaptive_levels.len(),
                    a.levels
                )?;
                for (k, l) in adaptive_levels.iter().enumerate() {
                    outln!(
                        "level {}: {} faces -> {}: {} refined, {} refined by closure, {} conformed, {} kept",
                        k + 1,
                        l.faces_in,
                        l.faces_out,
                        l.refined,
                        l.closure_refined,
                        l.conformed,
                        l.kept
                    )?;
                }
            }
        }
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

/// The adaptive levels' records as JSON (an empty list for uniform subdivision).
fn adaptive_json(levels: &[AdaptiveLevel]) -> serde_json::Value {
    levels
        .iter()
        .map(|l| {
            json!({
                "faces_in": l.faces_in,
                "refined": l.refined,
                "closure_refined": l.closure_refined,
                "conformed": l.conformed,
                "kept": l.kept,
                "faces_out": l.faces_out,
            })
        })
        .collect()
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
