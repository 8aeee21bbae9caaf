//! The memory budget (issue 15): `--max-memory` refuses a grid predicted to need more before
//! meshing (exit 2, no output file) and stops refinement below it with a warning; its default
//! keeps every hostile reproducer inside an 8 GiB address space (no abort, no signal).

use solidkit_tests::{fixture, path_str};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

fn mesh(args: &[&str]) -> Output {
    Command::new(BIN)
        .arg("mesh")
        .args(args)
        .arg("--no-progress")
        .output()
        .expect("run solidkit")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn a_grid_over_the_memory_limit_is_refused_before_meshing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("gyroid.stl");
    let input = fixture("bench/gyroid-sphere.json");
    let o = mesh(&[
        path_str(&input),
        "--resolution",
        "256",
        "--max-memory",
        "64M",
        "-o",
        path_str(&out),
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(err.matches("error:").count(), 1, "{err}");
    assert!(
        err.contains("memory limit of 64 MiB") && err.contains("--max-memory"),
        "{err}"
    );
    assert!(!out.exists(), "no output file after a refusal");
}

#[test]
fn refinement_stops_at_the_memory_limit_with_a_warning() {
    // The gyroid-sphere at 128 cells refines for its thin features; 512 MiB holds the first
    // grid (about 2 800 surface bricks) but not the next (four times as many).
    let input = fixture("bench/gyroid-sphere.json");
    let o = mesh(&[
        path_str(&input),
        "--resolution",
        "128",
        "--max-memory",
        "512M",
        "--no-self-intersections",
        "--json",
    ]);
    let err = stderr(&o);
    assert!(err.contains("stopped by the memory limit"), "{err}");
    let r = solidkit_tests::success_json(&o);
    assert_eq!(r["refinement"], 1, "{r}");
    assert_eq!(
        (&r["closed"], &r["manifold"]),
        (&true.into(), &true.into()),
        "{r}"
    );
    let warnings = r["warnings"].as_array().expect("warnings");
    assert!(
        warnings
            .iter()
            .any(|w| w.as_str().unwrap_or("").contains("memory limit")),
        "{r}"
    );
}

#[test]
fn sizes_are_range_checked() {
    let input = fixture("bench/sphere.json");
    for bad in ["12Q", "1K", "-1G", "2000T", "nanG"] {
        let o = mesh(&[path_str(&input), "--max-memory", bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}: {}", stderr(&o));
    }
}

/// Every hostile reproducer, and issue 13's thin tube (which refines 16 times), within an 8 GiB
/// address space: each run ends with an exit code (0, 1 or 2), never an abort or a signal.
#[test]
#[cfg(target_os = "linux")]
fn hostile_inputs_stay_within_an_8_gib_address_space() {
    if Command::new("prlimit").arg("--version").output().is_err() {
        eprintln!("prlimit not installed: skipped");
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let tube = dir.path().join("tube.json");
    std::fs::write(
        &tube,
        r#"{"type":"difference","children":[
            {"type":"cylinder","radius":10.02,"height":2},
            {"type":"cylinder","radius":10,"height":3}]}"#,
    )
    .expect("write");
    let mut inputs: Vec<std::path::PathBuf> = std::fs::read_dir(fixture("hostile"))
        .expect("fixtures/hostile")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    inputs.sort();
    inputs.push(tube);
    for input in &inputs {
        for method in ["mc", "dc"] {
            let resolution = if input.ends_with("tube.json") {
                "128"
            } else {
                "32"
            };
            let o = Command::new("prlimit")
                .arg("--as=8589934592")
                .arg(BIN)
                .args(["mesh", path_str(input), "--method", method])
                .args([
                    "--resolution",
                    resolution,
                    "--no-progress",
                    "--no-self-intersections",
                ])
                .output()
                .expect("run prlimit");
            assert!(
                matches!(o.status.code(), Some(0..=2)),
                "{} ({method}): {:?}\n{}",
                input.display(),
                o.status,
                stderr(&o)
            );
        }
    }
}
