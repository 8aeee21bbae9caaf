//! `solidkit subdivide`: polygon mesh file → half-edge mesh → subdivision → file and report.

use crate::args::SubdivideArgs;
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
    let limits = Limits {
        max_faces: a.max_faces,
    };
    let start = Instant::now();
    let result = subdivide(&mesh, scheme, a.levels, &limits).map_err(|e| anyhow!("{name}: {e}"))?;
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
        println!("{}", report::to_json(&r, &extra)?);
    } else {
        println!("scheme: {scheme}, {} level(s)", a.levels);
        println!(
            "polygon mesh: {} vertices, {} edges, {} faces (largest {largest} corners)",
            result.vertex_count(),
            result.edge_count(),
            result.face_count()
        );
        println!("report of its triangles:");
        print!("{}", r.to_text());
        println!("time: {time_s:.3} s");
        println!("wrote: {}", a.output.display());
    }
    Ok(0)
}
