//! Command-line arguments (clap), the contract users and later front ends rely on.

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;

/// solidkit: CSG and implicit solid modeling, meshing and mesh checking.
#[derive(Debug, Parser)]
#[command(name = "solidkit", version, about)]
pub struct Cli {
    /// Worker threads (default: all cores; RAYON_NUM_THREADS is honoured).
    #[arg(long, global = true)]
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
    /// closed oriented 2-manifold.
    Check(CheckArgs),
}

/// Polygonization method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Method {
    /// Marching cubes.
    Mc,
}

/// Arguments of `solidkit mesh`.
#[derive(Debug, clap::Args)]
pub struct MeshArgs {
    /// The solid: a JSON tree (.json).
    pub input: PathBuf,
    /// Write the mesh here; the format follows the extension (.stl .obj .ply .off).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Cells along the longest side of the meshing bounds.
    #[arg(short, long, default_value_t = 128)]
    pub resolution: usize,
    /// Polygonization method.
    #[arg(long, value_enum, default_value_t = Method::Mc)]
    pub method: Method,
    /// Clip the solid to the box x0,y0,z0,x1,y1,z1 and mesh that (default: the solid's bounding
    /// box, unclipped). Needed for unbounded solids such as half-spaces.
    #[arg(long, value_parser = parse_bounds, allow_hyphen_values = true)]
    pub bounds: Option<[f64; 6]>,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `solidkit check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// The mesh file (.stl .obj .ply .off).
    pub mesh: PathBuf,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
}

fn parse_bounds(s: &str) -> Result<[f64; 6], String> {
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
    Ok(out)
}
