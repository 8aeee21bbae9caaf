//! `solidkit render`: a PNG of a solid (ray cast from its field), of a mesh (z-buffer) or of a
//! cross-section of a solid.

use crate::args::RenderArgs;

use crate::input;
use crate::output::outln;
use anyhow::{Result, anyhow};
use glam::DVec3;
use solidkit_kernel::{Aabb, Solid};
use solidkit_meshing::io::read_mesh;
use solidkit_meshing::render::field::render_field;
use solidkit_meshing::render::png_out::write_png;
use solidkit_meshing::render::raster::render_mesh;
use solidkit_meshing::render::section::render_section;
use solidkit_meshing::render::{Camera, shade};
use std::path::Path;
use std::time::Instant;

/// Renders the input and writes the PNG.
pub fn run(a: &RenderArgs) -> Result<u8> {
    let start = Instant::now();
    let image = if is_solid(&a.input) {
        let (mut solid, warnings) =
            input::load_solid_warned(&a.input, a.facets.into(), &a.allow_path, &a.define)?;
        for w in &warnings {
            crate::output::errln!("warning: {}", crate::escape::one_line(w));
        }
        let frame = match a.bounds {
            Some(b) => {
                let clip = to_box(b);
                solid = solid.intersection(&Solid::cuboid(clip.size()).translate(clip.center()));
                clip
            }
            None => solid.bbox(),
        };
        let name = a.input.display();
        let program = solid.compile();
        match a.section {
            Some(section) => render_section(&program, &frame, section, a.size)
                .map_err(|e| anyhow!("{name}: {e}"))?,
            None => {
                let cam =
                    Camera::framing(a.view, &frame, a.size).map_err(|e| anyhow!("{name}: {e}"))?;
                render_field(&program, &cam, shade::SOLID)
            }
        }
    } else {
        if a.section.is_some() {
            return Err(anyhow!(
                "--section needs a solid (.json, .rhai or .csg), not a mesh file"
            ));
        }
        let mesh = read_mesh(&a.input)?;
        let frame = a.bounds.map_or_else(|| mesh_box(&mesh.positions), to_box);
        let cam = Camera::framing(a.view, &frame, a.size)
            .map_err(|e| anyhow!("{}: {e}", a.input.display()))?;
        render_mesh(&mesh, &cam, shade::SOLID)
    };
    let time_s = start.elapsed().as_secs_f64();
    write_png(&a.output, &image)?;
    outln!("time: {time_s:.3} s")?;
    outln!("wrote: {}", a.output.display())?;
    Ok(0)
}

/// True for the inputs rendered from their field (by extension: the front ends' formats).
fn is_solid(path: &Path) -> bool {
    solidkit_frontends::load::Format::from_path(path).is_ok()
}

/// `--bounds` as a box.
fn to_box(b: [f64; 6]) -> Aabb {
    Aabb::new(DVec3::new(b[0], b[1], b[2]), DVec3::new(b[3], b[4], b[5]))
}

/// The box of the finite positions (empty when there are none).
pub fn mesh_box(positions: &[DVec3]) -> Aabb {
    positions
        .iter()
        .filter(|p| p.is_finite())
        .fold(Aabb::empty(), |b, &p| Aabb::new(b.min.min(p), b.max.max(p)))
}
