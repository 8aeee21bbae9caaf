//! `solidkit gallery` (issue 18): docs/gallery.md and its pictures are what the examples give
//! today (CI fails on drift), and `--check` notices a changed picture, a changed page, a missing
//! picture and a stale one.

use solidkit_meshing::render::png_out::{decode, encode};
use solidkit_tests::{fixture, path_str, run_cli};
use std::path::PathBuf;

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

fn docs(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../docs")
        .join(rel)
}

#[test]
fn docs_gallery_is_up_to_date() {
    let o = run_cli(
        BIN,
        &[
            "gallery",
            path_str(&fixture("examples")),
            "-o",
            path_str(&docs("gallery.md")),
            "--check",
        ],
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "docs/gallery.md drifted; regenerate from the repository root with \
         `solidkit gallery fixtures/examples -o docs/gallery.md`:\n{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    let readme = std::fs::read_to_string(docs("../README.md")).expect("README");
    assert!(
        readme.contains("docs/gallery.md"),
        "the README links the gallery"
    );
}

#[test]
fn check_notices_drift() {
    let dir = tempfile::tempdir().expect("tempdir");
    let examples = dir.path().join("examples");
    std::fs::create_dir(&examples).expect("mkdir");
    for name in ["bracket.json", "icosahedron.obj"] {
        std::fs::copy(fixture(&format!("examples/{name}")), examples.join(name)).expect("copy");
    }
    let page = dir.path().join("docs/gallery.md");
    std::fs::create_dir(dir.path().join("docs")).expect("mkdir");
    let args = |check: bool| {
        let mut a = vec![
            "gallery",
            path_str(&examples),
            "-o",
            path_str(&page),
            "--size",
            "96x96",
        ];
        if check {
            a.push("--check");
        }
        a
    };
    let code = |check: bool| run_cli(BIN, &args(check)).status.code();
    assert_eq!(code(true), Some(1), "nothing written yet");
    assert_eq!(code(false), Some(0));
    assert_eq!(code(true), Some(0), "fresh gallery");
    let text = std::fs::read_to_string(&page).expect("page");
    assert!(text.contains("(gallery/bracket-json.png)") && text.contains("icosahedron.obj"));
    assert!(text.contains("genus 3"), "bracket's report line: {text}");
    let png = dir.path().join("docs/gallery/bracket-json.png");
    let original = std::fs::read(&png).expect("png");
    let mut image = decode(&original).expect("decode");
    // A few pixels changed are within the tolerance; a blotch is drift.
    for p in image.pixels.iter_mut().take(5) {
        *p = [0, 0, 0];
    }
    std::fs::write(&png, encode(&image).expect("encode")).expect("write");
    assert_eq!(code(true), Some(0), "5 pixels are within the tolerance");
    for p in image.pixels.iter_mut().take(400) {
        *p = [0, 0, 0];
    }
    std::fs::write(&png, encode(&image).expect("encode")).expect("write");
    assert_eq!(code(true), Some(1), "a changed picture");
    std::fs::write(&png, &original).expect("restore");
    std::fs::write(&page, text.replace("genus 3", "genus 4")).expect("edit page");
    assert_eq!(code(true), Some(1), "a changed page");
    std::fs::write(&page, &text).expect("restore page");
    std::fs::write(dir.path().join("docs/gallery/old.png"), &original).expect("stale");
    assert_eq!(code(true), Some(1), "a stale picture");
    assert_eq!(code(false), Some(0));
    assert!(
        !dir.path().join("docs/gallery/old.png").exists(),
        "stale picture removed"
    );
    std::fs::remove_file(&png).expect("remove");
    assert_eq!(code(true), Some(1), "a missing picture");
}
