//! Command-line arguments (clap), the contract users and later front ends rely on.

mod curve;
mod r#gen;
mod memory;
mod render;

pub use curve::CurveArgs;
pub use r#gen::GenArgs;
pub use render::{GalleryArgs, RenderArgs, parse_size, parse_view};
pub use solidkit_meshing::pipeline::limits::default_max_memory;

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// solidkit: CSG and implicit solid modeling, meshing and mesh checking.
#[derive(Debug, Parser)]
#[command(name = "solidkit", version, about)]
pub struct Cli {
    /// Worker threads (default: all cores; RAYON_NUM_THREADS is honoured), 1 to 16 per core
    /// (at least 64).
    #[arg(long, global = true, value_parser = parse_threads)]
    pub threads: Option<usize>,
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Mesh a solid and print its topology report.
    Mesh(MeshArgs),
    /// Read a mesh (STL, OBJ, PLY, OFF) and print its topology report; exit 1 unless it is a
    /// closed oriented 2-manifold without self-intersections.
    Check(CheckArgs),
    /// Write the JSON tree of any input (.json, .rhai, .csg).
    Convert(ConvertArgs),
    /// Write a suite of test solids with exact ground truth (one mesh per solid and
    /// manifest.json); exit 1 if a solid fails its own check.
    Gen(GenArgs),
    /// Compare two meshes: key measures of each and their symmetric Hausdorff distance.
    Compare(CompareArgs),
    /// Benchmark meshing of the standard models and print a table (time, rate, peak memory and
    /// the check of each mesh); exit 1 if a mesh fails its check.
    Bench(BenchArgs),
    /// One benchmark case, run by `bench` in a child process so its peak memory is its own.
    #[command(hide = true)]
    BenchCase(BenchCaseArgs),
    /// Subdivide a polygon mesh (Catmull-Clark, Loop, butterfly, Doo-Sabin), write it and print
    /// the topology report of the result.
    Subdivide(SubdivideArgs),
    /// Gaussian, mean and principal curvatures per vertex, written as PLY vertex properties
    /// (discrete for a mesh file, exact for a tree whose root is a parametric surface), with a
    /// summary and the Gauss-Bonnet check.
    Curvature(CurvatureArgs),
    /// Render a PNG: a solid ray cast from its field, a mesh file rasterised, or a
    /// cross-section (--section z=C) of a solid.
    Render(RenderArgs),
    /// Write a gallery page: a picture and the report line of every example in a folder
    /// (--check: compare with the page there instead, exit 1 on drift).
    Gallery(GalleryArgs),
    /// Repair a mesh into a closed oriented manifold without self-intersections (weld, clean,
    /// orient, fill holes, split non-manifold vertices; or remesh its winding-number solid),
    /// write it and print the reports before and after; exit 1 if the result is still not one.
    Repair(RepairArgs),
    /// Evaluate a curve given in JSON (Bézier, Hermite, B-spline, NURBS, interpolating,
    /// cubic_through, composite, formula): point and derivatives at a parameter, de Casteljau
    /// split, arc length, and a polyline within a chord-error bound (.obj, .svg, .json).
    Curve(CurveArgs),
}

/// How `solidkit repair` works.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum RepairMode {
    /// Topological fixes only; no vertex moves further than --weld.
    Minimal,
    /// Remesh the winding-number solid by dual contouring.
    Rebuild,
    /// Minimal, then rebuild if the result is still not a valid solid.
    Auto,
}

/// Arguments of `solidkit repair`.
#[derive(Debug, clap::Args)]
pub struct RepairArgs {
    /// The mesh file (.stl .obj .ply .off .3mf .glb).
    pub mesh: PathBuf,
    /// Write the repaired mesh here (replaced atomically; nothing is written on bad input).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Repair mode.
    #[arg(long, value_enum, default_value_t = RepairMode::Auto)]
    pub mode: RepairMode,
    /// Weld vertices closer than this (model units; default 1e-6 of the bounding-box diagonal,
    /// 0 welds equal positions only).
    #[arg(long, value_parser = parse_weld)]
    pub weld: Option<f64>,
    /// Rebuild: grid cells along the longest side (1 to 2048; default 128).
    #[arg(short, long, value_parser = parse_resolution, conflicts_with = "tolerance")]
    pub resolution: Option<usize>,
    /// Rebuild: cell size and dual contouring's collapse tolerance (model units).
    #[arg(long, value_parser = parse_tolerance)]
    pub tolerance: Option<f64>,
    /// Skip the self-intersection test of the result (then exit 0 means closed, oriented and
    /// manifold, self-intersections not checked; auto mode rebuilds only for the other defects).
    #[arg(long)]
    pub no_self_intersections: bool,
    /// Print JSON: {"before", "after", "changes", "rebuild", ...}.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `solidkit curvature`.
#[derive(Debug, clap::Args)]
pub struct CurvatureArgs {
    /// A mesh file (.stl .obj .ply .off .3mf .glb: discrete curvatures) or a tree (.json .rhai)
    /// whose root is a parametric surface or height field node (exact curvatures at its
    /// tessellation's vertices; the Laplacian Δh too where the sheet is a graph z = h(x, y)).
    pub input: PathBuf,
    /// Write the mesh here as binary PLY with the vertex properties gaussian, mean, k1, k2,
    /// boundary and, for a graph z = h(x, y), laplacian (replaced atomically).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Folders besides the input's own that files named in a tree may come from.
    #[arg(long, value_name = "DIR")]
    pub allow_path: Vec<PathBuf>,
    /// Print the summary as JSON.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `solidkit subdivide`.
#[derive(Debug, clap::Args)]
pub struct SubdivideArgs {
    /// The mesh file (.obj .off .ply keep polygonal faces; .stl gives triangles).
    pub mesh: PathBuf,
    /// Write the subdivided mesh here (replaced atomically); .obj .off .ply keep its polygons,
    /// .stl gets them triangulated.
    #[arg(short, long)]
    pub output: PathBuf,
    /// The subdivision scheme.
    #[arg(long, value_enum)]
    pub scheme: SchemeArg,
    /// How many times to apply it (0 to 30; with --adaptive at most this many).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(0..=30))]
    pub levels: u32,
    /// Adaptive (loop, catmull-clark): refine only faces that the next level would move off
    /// their plane by more than this distance (model units); red-green closure for Loop,
    /// conforming polygons for Catmull-Clark, so the result stays crack-free and manifold.
    #[arg(long, value_parser = parse_tolerance, allow_hyphen_values = true)]
    pub adaptive: Option<f64>,
    /// Refuse (before any work) a request whose last level would have more faces than this
    /// (also refused: more faces than half of this machine's memory holds, about 1 KiB each).
    #[arg(long, default_value_t = solidkit_meshing::subdivision::Limits::DEFAULT_MAX_FACES,
          value_parser = clap::value_parser!(u64).range(1..))]
    pub max_faces: u64,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}

/// `--scheme`: the subdivision schemes, by their JSON names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SchemeArg {
    /// Catmull-Clark: any polygons to quads (approximating).
    CatmullClark,
    /// Loop: triangles (approximating).
    Loop,
    /// Modified butterfly: triangles (interpolating: the vertices stay).
    Butterfly,
    /// Doo-Sabin: any polygons (dual, approximating).
    DooSabin,
}

impl From<SchemeArg> for solidkit_meshing::subdivision::Scheme {
    fn from(s: SchemeArg) -> Self {
        match s {
            SchemeArg::CatmullClark => Self::CatmullClark,
            SchemeArg::Loop => Self::Loop,
            SchemeArg::Butterfly => Self::Butterfly,
            SchemeArg::DooSabin => Self::DooSabin,
        }
    }
}

/// Polygonization method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Marching cubes.
    Mc,
    /// Manifold dual contouring (sharp features kept; `--tolerance` simplifies).
    Dc,
}

impl From<Method> for solidkit_meshing::pipeline::Method {
    fn from(m: Method) -> Self {
        match m {
            Method::Mc => solidkit_meshing::pipeline::Method::Mc,
            Method::Dc => solidkit_meshing::pipeline::Method::Dc,
        }
    }
}

impl Method {
    /// The method's name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Mc => "mc",
            Method::Dc => "dc",
        }
    }
}

/// How `solidkit mesh` makes the mesh: a polygonization method, or polyhedral Booleans.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MeshMethod {
    /// Marching cubes.
    Mc,
    /// Manifold dual contouring (sharp features kept; `--tolerance` simplifies).
    Dc,
    /// Mesh Booleans of the model's polyhedra (no grid).
    Polyhedral,
}

/// Arguments of `solidkit mesh`.
#[derive(Debug, clap::Args)]
pub struct MeshArgs {
    /// The solid: a JSON tree (.json) or a Rhai script (.rhai).
    pub input: PathBuf,
    /// Write the mesh here; the format follows the extension (.stl .obj .ply .off .3mf .glb).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Cells along the longest side of the meshing bounds (1 to 2048).
    #[arg(short, long, default_value_t = 128, value_parser = parse_resolution)]
    pub resolution: usize,
    /// Polygonization method (default: mc; dc with --target-error). `polyhedral`: no grid,
    /// mesh Booleans of the model's polyhedra (OpenSCAD's faceted parts of a .csg/.scad model,
    /// implying --facets openscad; trees of polyhedra, boxes, transforms and Booleans), as
    /// OpenSCAD and manifold3d build them; a part that is not a polyhedron is meshed alone by
    /// marching cubes with --resolution cells along its own longest side and combined exactly
    /// with the rest, with a warning naming it.
    #[arg(long, value_enum)]
    pub method: Option<MeshMethod>,
    /// Dual contouring only: collapse octree cells whose merged vertex stays within this
    /// distance (model units) of the surface planes it replaces, where the topology allows.
    #[arg(long, value_parser = parse_tolerance, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Simplify the mesh by edge collapses that keep it closed, manifold, oriented, of the same
    /// genus and free of self-intersections, with every point within this distance (model units)
    /// of the exact surface and the exact surface within it of the mesh (see
    /// docs/small-meshes.md); either method.
    #[arg(long, value_parser = parse_tolerance, allow_hyphen_values = true)]
    pub simplify: Option<f64>,
    /// The mesh within this distance (model units) of the exact surface, with as few triangles
    /// as the checks allow: dual contouring (sharp edges and corners kept) then `--simplify E`.
    /// The resolution still decides which features are found.
    #[arg(long, value_parser = parse_tolerance, allow_hyphen_values = true,
          conflicts_with_all = ["tolerance", "simplify"])]
    pub target_error: Option<f64>,
    /// Clip the solid to the box x0,y0,z0,x1,y1,z1 and mesh that (default: the solid's bounding
    /// box, unclipped). Needed for unbounded solids such as half-spaces.
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    pub bounds: Option<[f64; 6]>,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
    /// How round primitives of OpenSCAD `.csg` inputs are built: exact (true spheres, cylinders)
    /// or faceted exactly as OpenSCAD does.
    #[arg(long, value_enum, default_value_t = FacetsArg::Exact)]
    pub facets: FacetsArg,
    /// Skip the self-intersection count of the report.
    #[arg(long)]
    pub no_self_intersections: bool,
    /// Write no colours: by default the tree's `color` nodes colour the triangles of 3MF
    /// (basematerials), PLY (face red/green/blue/alpha) and GLB (a material per colour) output.
    #[arg(long)]
    pub no_colors: bool,
    /// No progress bar (one is drawn on standard error when it is a terminal and meshing takes
    /// more than half a second).
    #[arg(long)]
    pub no_progress: bool,
    /// Let the files the input names (`mesh` and `png` paths) come from DIR too (repeatable).
    /// Without it they must lie inside the input's own folder: relative paths, no `..` or
    /// symbolic link leading out, no absolute paths.
    #[arg(long, value_name = "DIR")]
    pub allow_path: Vec<PathBuf>,
    /// A variable for `.scad` inputs (passed to OpenSCAD as `-D NAME=VALUE`) and `.rhai` scripts
    /// (the constant NAME, VALUE a Rhai literal); repeatable.
    #[arg(short = 'D', value_name = "NAME=VALUE")]
    pub define: Vec<String>,
    /// Also write a PNG of the mesh (iso view, 1024x1024).
    #[arg(long, value_name = "PNG")]
    pub preview: Option<PathBuf>,
    /// Mesh again on grids up to this many times finer (1, 2, 4, 8, 16 or 32; 1: never) when
    /// features thinner than a cell are lost or thinned all along the surface.
    #[arg(long, default_value_t = 32, value_parser = parse_refine)]
    pub refine: usize,
    /// Most samples a refined run may be expected to evaluate (1000 to 2 000 000 000).
    #[arg(long, default_value_t = 64_000_000, value_parser = parse_refine_budget)]
    pub refine_budget: u64,
    /// Most memory the mesh and its report may be predicted to need (bytes, or a number with K,
    /// M, G or T); a grid predicted to need more is refused before meshing (exit 2) and
    /// refinement stops below it. Default: half of this machine's memory.
    #[arg(long, value_name = "SIZE", value_parser = memory::parse_memory)]
    pub max_memory: Option<u64>,
}

fn parse_refine(s: &str) -> Result<usize, String> {
    let f = parse_in_range(s, 1, 32, "a refinement factor")?;
    if f.is_power_of_two() {
        Ok(f)
    } else {
        Err(format!("{s}: expected 1, 2, 4, 8, 16 or 32"))
    }
}

fn parse_refine_budget(s: &str) -> Result<u64, String> {
    parse_in_range(s, 1000, 2_000_000_000, "a number of samples").map(|n| n as u64)
}

/// `--facets`: round primitives of `.csg` inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FacetsArg {
    /// True spheres, cylinders, cones and discs.
    Exact,
    /// OpenSCAD's polyhedra ($fn/$fa/$fs fragment rule).
    Openscad,
}

impl From<FacetsArg> for solidkit_frontends::csg::Facets {
    fn from(f: FacetsArg) -> Self {
        match f {
            FacetsArg::Exact => Self::Exact,
            FacetsArg::Openscad => Self::OpenScad,
        }
    }
}

/// Arguments of `solidkit check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// The mesh file (.stl .obj .ply .off .3mf .glb).
    pub mesh: PathBuf,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
    /// Weld vertices within EPS (model units; 0: equal positions) before the report, so a
    /// triangle soup's corners count as shared vertices.
    #[arg(long, value_name = "EPS", value_parser = parse_weld)]
    pub weld: Option<f64>,
    /// Skip the self-intersection count (a self-intersecting mesh then passes).
    #[arg(long)]
    pub no_self_intersections: bool,
    /// Also report V, E, F and V − E + F of the polygon mesh as the file has its faces (OBJ, OFF
    /// and PLY quads, pentagons… counted as one face each, vertex indices as in the file, before
    /// any --weld), beside the counts of its triangles.
    #[arg(long)]
    pub polygons: bool,
    /// Also write a PNG of the mesh in grey with its defects in colour and a legend.
    #[arg(long, value_name = "PNG")]
    pub render: Option<PathBuf>,
    /// Size WxH of the --render image.
    #[arg(long, default_value = "1024x1024", value_parser = parse_size)]
    pub size: solidkit_meshing::render::ImageSize,
    /// View of the --render image: iso, front, top, side or AZ,EL in degrees.
    #[arg(long, default_value = "iso", value_parser = parse_view, allow_hyphen_values = true)]
    pub view: solidkit_meshing::render::View,
    /// Also write the offending faces and edges as an ASCII PLY, coloured as in --render (faces
    /// and `edge` elements with red, green, blue and a class code), for other viewers.
    #[arg(long, value_name = "PLY")]
    pub export_defects: Option<PathBuf>,
}

/// Arguments of `solidkit compare`.
#[derive(Debug, clap::Args)]
pub struct CompareArgs {
    /// The first mesh (.stl .obj .ply .off .3mf .glb); relative distances use its bounding-box
    /// diagonal.
    pub a: PathBuf,
    /// The second mesh.
    pub b: PathBuf,
    /// Area-weighted sample points per mesh (all vertices are sampled as well), at most
    /// 10 000 000.
    #[arg(long, default_value_t = 100_000, value_parser = parse_samples)]
    pub samples: usize,
    /// Print JSON: {"a": report, "b": report, "hausdorff": {...}}.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `solidkit convert`.
#[derive(Debug, clap::Args)]
pub struct ConvertArgs {
    /// The solid: a JSON tree (.json), a Rhai script (.rhai) or an OpenSCAD .csg file.
    pub input: PathBuf,
    /// Write the JSON tree here (replaced atomically).
    #[arg(short, long)]
    pub output: PathBuf,
    /// How round primitives of OpenSCAD `.csg` inputs are built: exact (true spheres, cylinders)
    /// or faceted exactly as OpenSCAD does (the tree then holds OpenSCAD's polyhedra, slices and
    /// steps, as `mesh --facets openscad` meshes them).
    #[arg(long, value_enum, default_value_t = FacetsArg::Exact)]
    pub facets: FacetsArg,
    /// Let the files the input names (`mesh` and `png` paths) come from DIR too (repeatable).
    /// Without it they must lie inside the input's own folder: relative paths, no `..` or
    /// symbolic link leading out, no absolute paths.
    #[arg(long, value_name = "DIR")]
    pub allow_path: Vec<PathBuf>,
    /// A variable for `.scad` inputs (passed to OpenSCAD as `-D NAME=VALUE`) and `.rhai` scripts
    /// (the constant NAME, VALUE a Rhai literal); repeatable.
    #[arg(short = 'D', value_name = "NAME=VALUE")]
    pub define: Vec<String>,
}

/// Arguments of `solidkit bench`.
#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    /// Models, comma-separated: sphere, gyroid-sphere, menger-L, many-N (default: sphere,
    /// gyroid-sphere, menger-4, many-8456).
    #[arg(long, value_delimiter = ',')]
    pub model: Vec<String>,
    /// Resolutions, comma-separated, for every model (cells along the longest side of the
    /// model's domain; default: each model's own list), 1 to 2048.
    #[arg(long, value_delimiter = ',', value_parser = parse_resolution)]
    pub resolution: Vec<usize>,
    /// Runs per case (1 to 1000); the table shows the median, minimum and maximum time.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub repeat: u32,
    /// Measure the raw single-thread evaluation rates (points/s, boxes/s) instead of meshing;
    /// `--model` then picks among sphere, gyroid-sphere and many-8456.
    #[arg(long)]
    pub raw: bool,
    /// Run the cases in this process (faster to start; no peak memory).
    #[arg(long)]
    pub in_process: bool,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Polygonization methods, comma-separated: mc, dc (each case runs with each).
    #[arg(long, value_enum, value_delimiter = ',', default_value = "mc")]
    pub method: Vec<Method>,
    /// Thread scaling: worker-thread counts, comma-separated (e.g. `1,2`); each case runs with
    /// each, and the table's `speed-up` column gives the first count's median meshing and whole
    /// run times over each row's.
    #[arg(long, value_delimiter = ',', value_parser = parse_threads)]
    pub scaling: Vec<usize>,
}

/// Arguments of the hidden `solidkit bench-case` (one case; prints one JSON line).
#[derive(Debug, clap::Args)]
pub struct BenchCaseArgs {
    /// The model's name.
    #[arg(long)]
    pub model: String,
    /// Cells along the longest side of the model's domain.
    #[arg(long, value_parser = parse_resolution)]
    pub resolution: usize,
    /// Runs.
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub repeat: u32,
    /// Polygonization method.
    #[arg(long, value_enum, default_value_t = Method::Mc)]
    pub method: Method,
}

fn parse_tolerance(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
        _ => Err(format!("'{s}' is not a positive number")),
    }
}

fn parse_weld(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(t) if t.is_finite() && t >= 0.0 => Ok(t),
        _ => Err(format!("'{s}' is not a number >= 0")),
    }
}

pub(crate) fn parse_bounds(s: &str) -> Result<[f64; 6], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 6 {
        return Err(format!(
            "expected 6 comma-separated numbers, found {}",
            parts.len()
        ));
    }
    let mut out = [0.0; 6];
    for (o, p) in out.iter_mut().zip(&parts) {
        *o = p
            .parse::<f64>()
            .map_err(|_| format!("'{p}' is not a number"))?;
        if !o.is_finite() {
            return Err(format!("'{p}' is not a finite number"));
        }
    }
    if (0..3).any(|i| out[i] >= out[i + 3]) {
        return Err("each minimum must be below its maximum".into());
    }
    if (0..3).any(|i| !(out[i + 3] - out[i]).is_finite()) {
        return Err("the box is too large (its size overflows)".into());
    }
    Ok(out)
}

pub use solidkit_meshing::pipeline::limits::MAX_RESOLUTION;

/// The most area-weighted samples `compare` takes per mesh (each costs a distance query and
/// about 50 bytes).
pub const MAX_SAMPLES: usize = 10_000_000;

/// An unsigned integer in `lo..=hi`, with a message naming the range.
fn parse_in_range(s: &str, lo: usize, hi: usize, what: &str) -> Result<usize, String> {
    match s.trim().parse::<usize>() {
        Ok(n) if (lo..=hi).contains(&n) => Ok(n),
        _ => Err(format!("'{s}' is not {what} from {lo} to {hi}")),
    }
}

fn parse_resolution(s: &str) -> Result<usize, String> {
    parse_in_range(s, 1, MAX_RESOLUTION, "a whole number of cells")
}

fn parse_samples(s: &str) -> Result<usize, String> {
    parse_in_range(s, 0, MAX_SAMPLES, "a whole number of samples")
}

/// The most worker threads accepted: 16 per core, at least 64 (more only adds overhead; 100 000
/// threads took over a minute to start).
pub fn max_threads() -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    (16 * cores).max(64)
}

fn parse_threads(s: &str) -> Result<usize, String> {
    parse_in_range(s, 1, max_threads(), "a number of threads")
}
