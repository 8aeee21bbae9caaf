//! Arguments of `solidkit curve`.

use std::path::PathBuf;

/// Arguments of `solidkit curve`.
#[derive(Debug, clap::Args)]
pub struct CurveArgs {
    /// The curve file: one JSON curve object (docs/json-format.md, "Curves").
    pub curve: PathBuf,
    /// Print the point at this parameter (in the curve's own domain, printed by the report).
    #[arg(long, allow_negative_numbers = true)]
    pub at: Option<f64>,
    /// With --at: print the first and second derivatives and the unit tangent there too.
    #[arg(long, requires = "at")]
    pub tangent: bool,
    /// Split the Bézier piece holding this parameter by de Casteljau's algorithm and print the
    /// control points of both parts.
    #[arg(long, allow_negative_numbers = true)]
    pub split: Option<f64>,
    /// With -o: this many points at equally spaced parameters (2 to 10000000) instead of a
    /// chord-error bound.
    #[arg(long, conflicts_with = "chord_error",
          value_parser = clap::value_parser!(u64).range(2..=10_000_000))]
    pub samples: Option<u64>,
    /// With -o: the largest distance from the curve to the polyline (model units; default 1e-4
    /// of the curve's size). Certified for curves with control points, estimated from samples
    /// for formula curves.
    #[arg(long)]
    pub chord_error: Option<f64>,
    /// Write the polyline here (replaced atomically): .obj (`v` and `l` lines), .svg (a path of
    /// the xy projection) or .json ({"params", "points", ...}).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}
