//! The `solidkit` command: mesh CSG trees, check meshes.
//!
//! Exit codes: 0 success; 1 `check` found a mesh that is not a closed oriented 2-manifold;
//! 2 bad input or usage (one line on stderr naming the file, the place and the problem).

mod args;
mod commands;
mod escape;
mod input;
mod output;
mod progress;
mod report;

use clap::Parser;
use output::errln;
use std::process::ExitCode;

fn main() -> ExitCode {
    clean_up_on_signals();
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    // RAYON_NUM_THREADS is range-checked like --threads (rayon would start any number).
    let from_env = || {
        let v = std::env::var("RAYON_NUM_THREADS").ok()?;
        let n = v.trim().parse::<usize>().ok()?;
        (n > args::max_threads()).then_some(n)
    };
    if cli.threads.is_none()
        && let Some(n) = from_env()
    {
        errln!(
            "error: RAYON_NUM_THREADS={n}: at most {} worker threads (16 per core)",
            args::max_threads()
        );
        return ExitCode::from(2);
    }
    if let Some(n) = cli.threads
        && let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
    {
        errln!("error: --threads {n}: {e}");
        return ExitCode::from(2);
    }
    match commands::run(cli.command) {
        Ok(code) => ExitCode::from(code),
        Err(e) => {
            errln!("error: {}", one_line(&e));
            ExitCode::from(2)
        }
    }
}

/// On SIGINT, SIGTERM or SIGHUP, removes the temporary output files being written and exits with
/// 128 + the signal number, as the default action's status reads in a shell (destructors do not
/// run when a signal ends the process, so they would stay behind).
fn clean_up_on_signals() {
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) {
            let _ = std::thread::Builder::new()
                .name("signals".into())
                .spawn(move || {
                    if let Some(signal) = signals.forever().next() {
                        solidkit_meshing::io::remove_temporary_files_and_exit(128 + signal);
                    }
                });
        }
    }
}

/// The error and its causes on one line, control characters escaped. A cause the message
/// already quotes (errors that show their source, as `MeshIoError::Io` does) is not repeated.
fn one_line(e: &anyhow::Error) -> String {
    let mut text = e.to_string();
    for cause in e.chain().skip(1) {
        let cause = cause.to_string();
        if !text.contains(&cause) {
            text.push_str(": ");
            text.push_str(&cause);
        }
    }
    escape::one_line(&text)
}
