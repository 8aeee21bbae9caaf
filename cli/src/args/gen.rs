//! Arguments of `solidkit gen`.

use anyhow::{Result, anyhow};
use clap::ValueEnum;
use solidkit_meshing::io::MeshFormat;
use solidkit_meshing::suites::{Suite, SuiteOptions};
use std::path::PathBuf;

/// The suite to generate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SuiteArg {
    /// Platonic solids, their duals and prisms (exact polyhedra).
    Platonic,
    /// Menger sponges, levels 0-4 (exact polyhedra).
    Sponge,
    /// Parametric tessellations with a chord-error bound.
    Smooth,
    /// CSG solids polygonised by solidkit.
    Csg,
    /// Random CSG trees from --seed (volumes by sampling).
    Random,
    /// Meshes with known defects.
    Broken,
}

/// Mesh file format of `gen`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    /// Binary STL (32-bit floats; vertices welded by position when read).
    Stl,
    /// Wavefront OBJ (exact decimal coordinates).
    Obj,
    /// Binary little-endian PLY with double coordinates (exact).
    Ply,
    /// OFF (exact decimal coordinates).
    Off,
    /// 3MF package (exact decimal coordinates).
    #[value(name = "3mf")]
    ThreeMf,
    /// glTF 2.0 binary (32-bit floats).
    Glb,
}

/// Arguments of `solidkit gen`.
#[derive(Debug, clap::Args)]
pub struct GenArgs {
    /// The suite.
    #[arg(value_enum)]
    pub suite: SuiteArg,
    /// Output folder (created if missing): one mesh per solid, trees, manifest.json.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Mesh file format.
    #[arg(long, value_enum, default_value_t = FormatArg::Ply)]
    pub format: FormatArg,
    /// Seed of the random suite and of every volume sampling.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// csg, random: marching-cubes cells along the longest side; smooth: segments per turn.
    #[arg(short, long, default_value_t = 64)]
    pub resolution: usize,
    /// random: how many trees.
    #[arg(long, default_value_t = 8)]
    pub count: usize,
}

impl GenArgs {
    /// The suite, its options and the mesh format, checked.
    pub fn resolve(&self) -> Result<(Suite, SuiteOptions, MeshFormat)> {
        let suite = match self.suite {
            SuiteArg::Platonic => Suite::Platonic,
            SuiteArg::Sponge => Suite::Sponge,
            SuiteArg::Smooth => Suite::Smooth,
            SuiteArg::Csg => Suite::Csg,
            SuiteArg::Random => Suite::Random,
            SuiteArg::Broken => Suite::Broken,
        };
        let format = match self.format {
            FormatArg::Stl => MeshFormat::Stl,
            FormatArg::Obj => MeshFormat::Obj,
            FormatArg::Ply => MeshFormat::Ply,
            FormatArg::Off => MeshFormat::Off,
            FormatArg::ThreeMf => MeshFormat::ThreeMf,
            FormatArg::Glb => MeshFormat::Glb,
        };
        let opts = SuiteOptions {
            seed: self.seed,
            resolution: self.resolution,
            count: self.count,
        };
        opts.check()
            .map_err(|e| anyhow!("gen {}: {e}", suite.name()))?;
        Ok((suite, opts, format))
    }
}
