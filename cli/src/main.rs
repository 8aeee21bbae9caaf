//! The `solidkit` command: mesh CSG trees, check meshes.
//!
//! Exit codes: 0 success; 1 `check` found a mesh that is not a closed oriented 2-manifold;
//! 2 bad input or usage (one line on stderr naming the file, the place and the problem).

mod args;
mod commands;
mod escape;
mod frontends;
mod input;
mod progress;
mod report;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    if let Some(n) = cli.threads
        && let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
    {
        eprintln!("error: --threads {n}: {e}");
        return ExitCode::from(2);
    }
    match commands::run(cli.command) {
        Ok(code) => ExitCode::from(code),
        Err(e) => {
            eprintln!("error: {}", one_line(&e));
            ExitCode::from(2)
        }
    }
}

/// The error and its causes on one line, control characters escaped.
fn one_line(e: &anyhow::Error) -> String {
    escape::one_line(&format!("{e:#}"))
}
