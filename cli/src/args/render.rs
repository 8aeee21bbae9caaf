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
    /// 1: the --view alone; 4: a 2x2 sheet of the iso, front, top and side views, each
    /// labelled, filling --size together.
    #[arg(long, default_value_t = 1, value_parser = parse_views, conflicts_with = "view")]
    pub views: u32,
    /// Draw feature edges: silhouettes, creases sharper than 40 degrees, occlusion steps.
    #[arg(long)]
    pub edges: bool,
    /// Draw the axis triad (x red, y green, z blue) in the lower-left corner of each view.
    #[arg(long)]
    pub axes: bool,
    /// Draw the cross-section x=C, y=C or z=C (filled by sign, zero contour dark) instead of
    /// the solid (trees, scripts and .csg only).
    #[arg(long, value_parser = parse_section, allow_hyphen_values = true,
          conflicts_with_all = ["views", "edges", "axes", "view"])]
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
    /// A variable for `.scad` inputs (passed to OpenSCAD as `-D NAME=VALUE`) and `.rhai` scripts
    /// (the constant NAME, VALUE a Rhai literal); repeatable.
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

/// `--views`: 1 or 4.
pub fn parse_views(s: &str) -> Result<u32, String> {
    match s.trim() {
        "1" => Ok(1),
        "4" => Ok(4),
        _ => Err(format!("'{s}': expected 1 or 4")),
    }
}

fn parse_section(s: &str) -> Result<Section, String> {
    Section::parse(s).map_err(|e| e.to_string())
}

/// Arguments of `solidkit gallery`.
#[derive(Debug, clap::Args)]
pub struct GalleryArgs {
    /// The folder of examples: every solid (.json .rhai .csg) and mesh file (.stl .obj .ply .off
    /// .3mf .glb) in it, by name (.scad files are left out: they need OpenSCAD).
    pub examples: PathBuf,
    /// The Markdown page to write; the pictures go to the folder beside it named after it
    /// (docs/gallery.md: docs/gallery/).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Size WxH of each picture.
    #[arg(long, default_value = "256x256", value_parser = parse_size)]
    pub size: ImageSize,
    /// Resolution solids are meshed at for their report line (16 to 512; no refinement).
    #[arg(long, default_value_t = 64, value_parser = parse_gallery_resolution)]
    pub resolution: usize,
    /// Write nothing: compare with the page and pictures there and exit 1 when they drifted
    /// (the page must match exactly, each picture within the tolerance of docs/gallery.md).
    #[arg(long)]
    pub check: bool,
}

fn parse_gallery_resolution(s: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(n) if (16..=512).contains(&n) => Ok(n),
        _ => Err(format!("'{s}': expected a resolution from 16 to 512")),
    }
}
