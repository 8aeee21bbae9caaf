//! Standard output that reports a failure (a closed pipe, a full disk) as an error naming it,
//! never a panic as `print!` does. Each call writes and flushes, so the error comes at once.

use anyhow::{Context, Result};
use std::io::Write;

/// Writes `args` to standard output and flushes it.
pub fn write(args: std::fmt::Arguments) -> Result<()> {
    let mut out = std::io::stdout().lock();
    out.write_fmt(args)
        .and_then(|()| out.flush())
        .context("cannot write to standard output")
}

/// `print!` returning `anyhow::Result<()>`.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::output::write(format_args!($($arg)*))
    };
}

/// `println!` returning `anyhow::Result<()>`.
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::output::write(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// `eprintln!` that ignores a failing standard error (there is nowhere left to report it)
/// instead of panicking.
macro_rules! errln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

pub(crate) use {errln, out, outln};
