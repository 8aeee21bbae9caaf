//! The subcommands, one file each.

mod bench;
mod check;
mod compare;
mod convert;
mod curvature;
mod curve;
mod gallery;
mod r#gen;
mod mesh;
mod mesh_extras;
mod mesh_polyhedral;
mod overlap;
mod render;
mod repair;
mod subdivide;

use crate::args::Command;
use anyhow::Result;

/// Runs a subcommand; returns the process exit code.
pub fn run(command: Command) -> Result<u8> {
    match command {
        Command::Mesh(a) => mesh::run(&a),
        Command::Check(a) => check::run(&a),
        Command::Convert(a) => convert::run(&a),
        Command::Gen(a) => r#gen::run(&a),
        Command::Compare(a) => compare::run(&a),
        Command::Bench(a) => bench::run(&a),
        Command::BenchCase(a) => bench::run_case(&a),
        Command::Subdivide(a) => subdivide::run(&a),
        Command::Curvature(a) => curvature::run(&a),
        Command::Render(a) => render::run(&a),
        Command::Gallery(a) => gallery::run(&a),
        Command::Repair(a) => repair::run(&a),
        Command::Curve(a) => curve::run(&a),
    }
}
