//! Every example in `fixtures/examples/` (`.json`, `.rhai`, `.csg`) meshed through the real binary
//! at resolution 96: closed, manifold, oriented, free of self-intersections, with the shell count
//! and genus its own `expect: shells=N genus=G` line states.

use serde_json::Value;
use solidkit_tests::fixture;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::thread;

/// The `(shells, genus)` of the first `expect: shells=N genus=G` line of `text`.
fn expectation(text: &str) -> Option<(u64, u64)> {
    let at = text.find("expect:")?;
    let mut words = text[at + "expect:".len()..].split_whitespace();
    let mut field = |name: &str| -> Option<u64> {
        let word = words.next()?.trim_end_matches(['"', '\\', ',']);
        word.strip_prefix(name)?.strip_prefix('=')?.parse().ok()
    };
    let shells = field("shells")?;
    let genus = field("genus")?;
    Some((shells, genus))
}

fn examples() -> Vec<PathBuf> {
    let dir = fixture("examples");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("read fixtures/examples")
        .map(|e| e.expect("directory entry").path())
        .filter(|p| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("json" | "rhai" | "csg")
            )
        })
        .collect();
    files.sort();
    files
}

fn check(path: &Path) -> Result<(), String> {
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("?");
    let text = std::fs::read_to_string(path).map_err(|e| format!("{name}: {e}"))?;
    let (shells, genus) =
        expectation(&text).ok_or_else(|| format!("{name}: no `expect: shells=N genus=G` line"))?;
    let o = Command::new(env!("CARGO_BIN_EXE_solidkit"))
        .args([
            "mesh",
            path.to_str().expect("UTF-8 path"),
            "--resolution",
            "96",
            "--json",
        ])
        .output()
        .map_err(|e| format!("{name}: run solidkit: {e}"))?;
    if !o.status.success() {
        return Err(format!("{name}: {}", String::from_utf8_lossy(&o.stderr)));
    }
    let r: Value = serde_json::from_slice(&o.stdout).map_err(|e| format!("{name}: {e}"))?;
    let mut problems = Vec::new();
    for key in ["closed", "manifold", "oriented"] {
        if r[key] != true {
            problems.push(format!("{key} = {}", r[key]));
        }
    }
    if r["shells"] != shells {
        problems.push(format!("shells = {}, expected {shells}", r["shells"]));
    }
    if r["genus"] != genus {
        problems.push(format!("genus = {}, expected {genus}", r["genus"]));
    }
    if r["self_intersections"] != 0 {
        problems.push(format!("self_intersections = {}", r["self_intersections"]));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!("{name}: {}", problems.join(", ")))
    }
}

#[test]
fn expectation_lines_parse() {
    assert_eq!(expectation("// expect: shells=2 genus=1\n"), Some((2, 1)));
    assert_eq!(
        expectation(r#""A ring.\nexpect: shells=1 genus=3""#),
        Some((1, 3))
    );
    assert_eq!(expectation("no line here"), None);
}

#[test]
fn every_example_meshes_with_its_expected_topology() {
    let files = examples();
    assert!(files.len() >= 15, "only {} examples", files.len());
    // A few binaries at a time: each meshes in parallel itself.
    let failures: Vec<String> = files
        .chunks(4)
        .flat_map(|chunk| {
            thread::scope(|s| {
                let handles: Vec<_> = chunk.iter().map(|p| s.spawn(move || check(p))).collect();
                handles
                    .into_iter()
                    .filter_map(|h| h.join().expect("example thread").err())
                    .collect::<Vec<_>>()
            })
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
