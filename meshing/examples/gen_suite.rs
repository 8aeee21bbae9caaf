//! Write a suite of test solids with exact ground truth: one mesh per solid and a manifest.
//!
//! `cargo run --release -p solidkit-meshing --features suites --example gen_suite [DIR]`

use solidkit_meshing::io::{MeshFormat, write_atomic};
use solidkit_meshing::suites::record::encode;
use solidkit_meshing::suites::{Manifest, Suite, SuiteOptions, generate};
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| std::env::temp_dir().join("platonic-suite"));
    std::fs::create_dir_all(&dir)?;

    // The Platonic solids, their duals and prisms, with closed-form volumes and areas.
    let suite = Suite::Platonic;
    let options = SuiteOptions::default();
    let format = MeshFormat::Stl;
    let mut records = Vec::new();
    for solid in generate(suite, &options)? {
        let encoded = encode(&solid, format)?;
        write_atomic(&dir.join(&encoded.record.file), |out| {
            out.write_all(&encoded.bytes)
        })?;
        records.push(encoded.record);
    }
    let manifest = Manifest::new(suite, &options, format, records);
    write_atomic(&dir.join("manifest.json"), |out| {
        out.write_all(manifest.to_json().as_bytes())
    })?;
    for record in &manifest.solids {
        println!("{}", record.file);
    }
    println!(
        "wrote {} meshes and manifest.json to {}",
        manifest.solids.len(),
        dir.display()
    );
    Ok(())
}
