//! Build a CSG tree in code, mesh it through the pipeline, check it and write it.
//!
//! `cargo run --release -p solidkit-meshing --example mesh_tree [OUT.stl]`

use glam::DVec3;
use solidkit_kernel::Solid;
use solidkit_meshing::io::write_mesh;
use solidkit_meshing::pipeline::{MeshOptions, Method, mesh_solid};
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A rounded bracket: a plate and an upright, with a hole through the upright.
    let plate = Solid::cuboid(DVec3::new(4.0, 2.0, 0.5));
    let upright = Solid::cuboid(DVec3::new(0.5, 2.0, 3.0)).translate(DVec3::new(-1.75, 0.0, 1.25));
    let hole = Solid::cylinder(0.4, 3.0)
        .rotate(DVec3::Y, 90.0)
        .translate(DVec3::new(-1.75, 0.0, 1.75));
    let bracket = plate.union(&upright).difference(&hole);
    bracket.validate()?;

    // Dual contouring keeps the box edges sharp.
    let options = MeshOptions::new(96).method(Method::Dc);
    let meshed = mesh_solid(&bracket, &options)?;
    for w in &meshed.warnings {
        eprintln!("warning: {w}");
    }
    let report = meshed.report(&Default::default());
    print!("{}", report.to_text());

    let out = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| std::env::temp_dir().join("bracket.stl"));
    write_mesh(&out, &meshed.mesh)?;
    println!("wrote: {}", out.display());
    Ok(())
}
