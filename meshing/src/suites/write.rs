//! A suite written to a folder: one mesh file per solid, the JSON tree beside each CSG mesh and
//! `manifest.json` last, each file written atomically. Solids are encoded and measured in
//! parallel; the bytes do not depend on the number of threads.

use super::record::{Encoded, encode};
use super::{Manifest, Suite, SuiteError, SuiteOptions, generate};
use crate::io::{MeshFormat, MeshIoError, write_atomic};
use rayon::prelude::*;
use std::path::Path;

/// Why a suite could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum WriteSuiteError {
    /// The options are out of range (or a solid could not be built).
    #[error("gen {suite}: {error}")]
    Suite {
        /// The suite's name.
        suite: &'static str,
        /// Why.
        error: SuiteError,
    },
    /// The folder cannot be created.
    #[error("{dir}: {error}")]
    Folder {
        /// The folder.
        dir: String,
        /// Why.
        error: std::io::Error,
    },
    /// A mesh could not be encoded or a file written.
    #[error(transparent)]
    Io(#[from] MeshIoError),
}

/// Generates `suite` with `options` and writes it into `dir` (created if missing); returns the
/// manifest written. Check [`Manifest::failures`] for the self-checks.
pub fn write_suite(
    dir: &Path,
    suite: Suite,
    options: &SuiteOptions,
    format: MeshFormat,
) -> Result<Manifest, WriteSuiteError> {
    let fail = |error| WriteSuiteError::Suite {
        suite: suite.name(),
        error,
    };
    options.check().map_err(fail)?;
    std::fs::create_dir_all(dir).map_err(|error| WriteSuiteError::Folder {
        dir: dir.display().to_string(),
        error,
    })?;
    let solids = generate(suite, options).map_err(fail)?;
    let encoded: Vec<Encoded> = solids
        .par_iter()
        .map(|s| encode(s, format))
        .collect::<Result<_, _>>()?;
    for e in &encoded {
        write_atomic(&dir.join(&e.record.file), |out| out.write_all(&e.bytes))?;
        if let (Some(text), Some(file)) = (&e.tree, &e.record.tree) {
            write_atomic(&dir.join(file), |out| out.write_all(text.as_bytes()))?;
        }
    }
    let records: Vec<_> = encoded.into_iter().map(|e| e.record).collect();
    let manifest = Manifest::new(suite, options, format, records);
    write_atomic(&dir.join("manifest.json"), |out| {
        out.write_all(manifest.to_json().as_bytes())
    })?;
    Ok(manifest)
}
