//! The CLI suites, one module per file, in one test binary: each runs the real `solidkit` binary
//! (Cargo builds it first and names it in `CARGO_BIN_EXE_solidkit`, so this root is declared in
//! `cli/Cargo.toml`). One binary instead of one per file: one release link instead of
//! twenty-three.
//!
//! Run one suite with a filter: `cargo test --release -p solidkit --test cli_suite cli_repair::`.

/// The CLI contract: commands, options, exit codes, JSON reports and output files.
#[path = "cli.rs"]
mod cli;
/// Colours (`color()` nodes) carried to 3MF, PLY and GLB.
#[path = "cli_colors.rs"]
mod cli_colors;
/// OpenSCAD `.csg` import, surface and offset (issue 14) against exact volumes.
#[path = "cli_csg_import.rs"]
mod cli_csg_import;
/// `solidkit curvature` (issue 21) through the real binary.
#[path = "cli_curvature.rs"]
mod cli_curvature;
/// `solidkit curve` on the notes' curves (issue 21).
#[path = "cli_curves.rs"]
mod cli_curves;
/// Formula solids (`expr`) through the real binary.
#[path = "cli_formulas.rs"]
mod cli_formulas;
/// The front ends (.rhai scripts, `convert`) through the real binary.
#[path = "cli_frontends.rs"]
mod cli_frontends;
/// `solidkit gallery` (issue 18): docs/gallery.md is up to date; --check notices drift.
#[path = "cli_gallery.rs"]
mod cli_gallery;
/// Hostile inputs (issue 15): aliased blends, radii, number ranges, standard output, sandbox.
#[path = "cli_hostile_core.rs"]
mod cli_hostile_core;
/// Hostile files (issue 15): confinement of tree paths, regular files and size caps, PNG limits,
/// no quoted foreign content, escaped control characters, strict JSON.
#[path = "cli_hostile_files.rs"]
mod cli_hostile_files;
/// Structure-aware fuzzing (issue 15): random well-formed trees with extreme parameters through
/// the binary; never a panic, a hang or a partial file.
#[path = "cli_hostile_fuzz.rs"]
mod cli_hostile_fuzz;
/// Hostile meshing (issue 15): the mesher's reduced crash fixtures (fixtures/hostile/), grids below
/// single precision, open mesh operands, the memory budget.
#[path = "cli_hostile_mesh.rs"]
mod cli_hostile_mesh;
/// `compare` (Hausdorff distance) and the self-intersection part of `check`, through the binary.
#[path = "cli_measure.rs"]
mod cli_measure;
/// The memory budget (issue 15): --max-memory refusals, refinement stopped below it, and the
/// hostile reproducers inside an 8 GiB address space.
#[path = "cli_memory.rs"]
mod cli_memory;
#[path = "cli_polyhedral.rs"]
mod cli_polyhedral;
/// `solidkit render`, `check --render` (issue 18): field vs mesh silhouettes, thread-count
/// determinism, defect colours where the defects are, exported defect PLY files, hostile sizes.
#[path = "cli_render.rs"]
mod cli_render;
/// `render --views 4 --edges --axes` (issue 18): the sheet's cells, edges on the silhouette, the
/// triad only when asked, thread-count determinism.
#[path = "cli_render_views.rs"]
mod cli_render_views;
/// `solidkit repair` (issue 19): a built-in broken suite and `gen broken`, minimal / rebuild / auto.
#[path = "cli_repair.rs"]
mod cli_repair;
/// `.scad` inputs through the installed OpenSCAD.
#[path = "cli_scad.rs"]
mod cli_scad;
/// `solidkit subdivide` and `subdivide` nodes through the real binary.
#[path = "cli_subdivide.rs"]
mod cli_subdivide;
/// Features thinner than a cell (issue 13): refinement, warnings, exit 1 for an empty mesh.
#[path = "cli_thin.rs"]
mod cli_thin;
/// Every example in fixtures/examples/ meshed with the topology its `expect:` line states.
#[path = "examples.rs"]
mod examples;
/// Small independent readers of the 3MF and GLB files solidkit writes (for `cli_colors` and
/// `gen_suites`).
#[path = "export_readers.rs"]
mod export_readers;
/// `solidkit gen`: exact ground truth of every suite, determinism, 3MF and GLB round trips.
#[path = "gen.rs"]
mod gen_suites;
