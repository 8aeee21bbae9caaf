//! Arguments of `solidkit render` and the image options `check --render` and `mesh --preview`
//! share.

use super::FacetsArg;
use solidkit_meshing::render::section::Section;
use solidkit_meshing::render::{ImageSize, View};
use std::path::PathBuf;

/// Arguments of `solidkit render`.
#[derive(Debug, clap::Args)]
pub struct RenderArgs {
    /// A solid (.json tree, .rhai script, .csg file: rendered from its field) or a mesh file
    /// (.stl .obj .ply .off .3mf .glb: rasterised).
    pub input: PathBuf,
    /// Write the PNG here (replaced atomically).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Image size WxH in pixels (at most 64 Mi pixels, 65536 per side).
    #[arg(long, default_value = "1024x1024", value_parser = parse_size)]
    pub size: ImageSize,
    /// View direction: iso, front (from -y), top (from +z), side (from +x) or AZ,EL in degrees.
    #[arg(long, default_value = "iso", value_parser = parse_view, allow_hyphen_values = true)]
    pub view: View,
    /// Draw the cross-section x=C, y=C or z=C (filled by sign, zero contour dark) instead of
    /// the solid (trees, scripts and .csg only).
    #[arg(long, value_parser = parse_section, allow_hyphen_values = true)]
    pub section: Option<Section>,
    /// Frame the box x0,y0,z0,x1,y1,z1 instead of the bounding box; a solid is clipped to it
    /// (needed for unbounded solids such as half-spaces).
    #[arg(long, value_parser = crate::args::parse_bounds, allow_hyphen_values = true)]
    pub bounds: Option<[f64; 6]>,
    /// How round primitives of OpenSCAD `.csg` inputs are built.
    #[arg(long, value_enum, default_value_t = FacetsArg::Exact)]
    pub facets: FacetsArg,
    /// Let the files the input names (`mesh` and `png` paths) come from DIR too (repeatable).
    #[arg(long, value_name = "DIR")]
    pub allow_path: Vec<PathBuf>,
    /// A variable for `.scad` inputs, passed to OpenSCAD as `-D NAME=VALUE` (repeatable).
    #[arg(short = 'D', value_name = "NAME=VALUE")]
    pub define: Vec<String>,
}

/// `WxH`, checked against the pixel cap before anything is allocated.
pub fn parse_size(s: &str) -> Result<ImageSize, String> {
    ImageSize::parse(s).map_err(|e| e.to_string())
}

/// A named view or `AZ,EL`.
pub fn parse_view(s: &str) -> Result<View, String> {
    View::parse(s).map_err(|e| e.to_string())
}

fn parse_section(s: &str) -> Result<Section, String> {
    Section::parse(s).map_err(|e| e.to_string())
}
