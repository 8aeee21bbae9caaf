//! `solidkit render`: a PNG of a solid (ray cast from its field), of a mesh (z-buffer) or of a
//! cross-section of a solid.

use crate::args::RenderArgs;

use crate::input;
use crate::output::outln;
use anyhow::{Result, anyhow};
use glam::DVec3;
use solidkit_kernel::files::{DEFAULT_MAX_FILE_BYTES, read_regular_file};
use solidkit_kernel::{Aabb, Solid};
use solidkit_meshing::io::{MeshFormat, read_mesh_bytes, stl_binary_records};
use solidkit_meshing::render::field::trace_field;
use solidkit_meshing::render::png_out::write_png;
use solidkit_meshing::render::raster::{StlRecords, Triangles, trace_mesh, triangles_box};
use solidkit_meshing::render::section::render_section;
use solidkit_meshing::render::{Image, Look, picture, shade};
use std::path::Path;
use std::time::Instant;

/// Renders the input and writes the PNG.
pub fn run(a: &RenderArgs) -> Result<u8> {
    let start = Instant::now();
    let look = Look {
        view: (a.views == 1).then_some(a.view),
        edges: a.edges,
        axes: a.axes,
        base: shade::SOLID,
    };
    let name = a.input.display();
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
        let program = solid.compile();
        match a.section {
            Some(section) => render_section(&program, &frame, section, a.size),
            None => picture(&frame, a.size, &look, |cam| trace_field(&program, cam)),
        }
        .map_err(|e| anyhow!("{name}: {e}"))?
    } else {
        if a.section.is_some() {
            return Err(anyhow!(
                "--section needs a solid (.json, .rhai or .csg), not a mesh file"
            ));
        }
        let format = MeshFormat::from_path(&a.input)?;
        let bytes = read_regular_file(&a.input, DEFAULT_MAX_FILE_BYTES)
            .map_err(|e| anyhow!("{name}: {e}"))?;
        let records = match format {
            MeshFormat::Stl => stl_binary_records(&bytes),
            _ => None,
        };
        // Binary STL is drawn straight from its records (no welding), unless a coordinate is
        // not finite, which the reader reports.
        match records.map(|r| (StlRecords(r), triangles_box(&StlRecords(r)))) {
            Some((stl, (frame, true))) => render_triangles(&stl, frame, a, &look)?,
            _ => {
                let mesh = read_mesh_bytes(&bytes, format, &name.to_string())?;
                let frame = triangles_box(&mesh).0;
                render_triangles(&mesh, frame, a, &look)?
            }
        }
    };
    let time_s = start.elapsed().as_secs_f64();
    write_png(&a.output, &image)?;
    outln!("time: {time_s:.3} s")?;
    outln!("wrote: {}", a.output.display())?;
    Ok(0)
}

/// The picture of a mesh, framing `frame` (its box) or `--bounds`.
fn render_triangles(
    mesh: &impl Triangles,
    frame: Aabb,
    a: &RenderArgs,
    look: &Look,
) -> Result<Image> {
    let frame = a.bounds.map_or(frame, to_box);
    picture(&frame, a.size, look, |cam| trace_mesh(mesh, cam))
        .map_err(|e| anyhow!("{}: {e}", a.input.display()))
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
