//! `solidkit render --views 4 --edges --axes` (issue 18) through the binary: the sheet has four
//! labelled, filled cells; feature edges cover the silhouette; the triad is drawn only when asked
//! and where it belongs; the bytes do not depend on the thread count, for fields and meshes.

use solidkit_meshing::render::axes::AXIS_COLORS;
use solidkit_meshing::render::edges::EDGE;
use solidkit_meshing::render::png_out::decode;
use solidkit_meshing::render::{Image, shade};
use solidkit_tests::{fixture, path_str, run_cli};
use std::path::Path;

const BIN: &str = env!("CARGO_BIN_EXE_solidkit");

fn ok(args: &[&str]) {
    let o = run_cli(BIN, args);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

fn read(path: &Path) -> Image {
    decode(&std::fs::read(path).expect("png")).expect("an RGB png")
}

/// Renders `input` with `extra` options at 400 x 400 into `out` and reads it back.
fn render(input: &Path, out: &Path, extra: &[&str]) -> Image {
    let mut args = vec![
        "render",
        path_str(input),
        "-o",
        path_str(out),
        "--size",
        "400x400",
    ];
    args.extend(extra);
    ok(&args);
    read(out)
}

/// A mesh of the bracket example, written into `dir`.
fn bracket_mesh(dir: &Path) -> std::path::PathBuf {
    let mesh = dir.join("bracket.stl");
    ok(&[
        "mesh",
        path_str(&fixture("examples/bracket.json")),
        "-r",
        "64",
        "-o",
        path_str(&mesh),
        "--no-self-intersections",
    ]);
    mesh
}

/// Counts the pixels of `color` in the rectangle `[x0, y0, x1, y1)`.
fn count(image: &Image, [x0, y0, x1, y1]: [u32; 4], color: [u8; 3]) -> usize {
    (y0..y1)
        .flat_map(|y| (x0..x1).map(move |x| (x, y)))
        .filter(|&(x, y)| image.get(x, y) == color)
        .count()
}

#[test]
fn sheet_has_four_labelled_filled_cells() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mesh = bracket_mesh(dir.path());
    for input in [fixture("examples/bracket.json"), mesh] {
        let out = dir.path().join("sheet.png");
        let sheet = render(&input, &out, &["--views", "4"]);
        let label = [60, 60, 60];
        for (k, name) in ["iso", "front", "top", "side"].iter().enumerate() {
            let (x0, y0) = (200 * (k as u32 % 2), 200 * (k as u32 / 2));
            let cell = [x0 + 1, y0 + 1, x0 + 199, y0 + 199];
            let solid = (cell[1]..cell[3])
                .flat_map(|y| (cell[0]..cell[2]).map(move |x| (x, y)))
                .filter(|&(x, y)| {
                    let p = sheet.get(x, y);
                    p != shade::BACKGROUND && p != label
                })
                .count();
            assert!(
                solid > 199 * 199 / 10,
                "{input:?} {name}: {solid} solid pixels"
            );
            let text = count(&sheet, [x0, y0, x0 + 60, y0 + 12], label);
            assert!(text > 10, "{input:?} {name}: no label ({text} pixels)");
        }
        // The four cells are different views, not one picture four times.
        let cell = |k: u32| {
            let (x0, y0) = (200 * (k % 2), 200 * (k / 2));
            (12..199)
                .flat_map(|y| (1..199).map(move |x| (x, y)))
                .map(|(x, y)| sheet.get(x0 + x, y0 + y))
                .collect::<Vec<_>>()
        };
        for (a, b) in [(0, 1), (1, 2), (2, 3), (0, 3)] {
            assert!(cell(a) != cell(b), "{input:?}: cells {a} and {b} alike");
        }
    }
}

#[test]
fn edges_outline_the_silhouette_and_axes_only_when_asked() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mesh = bracket_mesh(dir.path());
    for input in [fixture("examples/bracket.json"), mesh] {
        let plain = render(&input, &dir.path().join("plain.png"), &[]);
        let edged = render(&input, &dir.path().join("edged.png"), &["--edges"]);
        let whole = [0, 0, 400, 400];
        assert_eq!(
            count(&plain, whole, EDGE),
            0,
            "{input:?}: edges without --edges"
        );
        // Every surface pixel next to the background is an edge pixel; edges only cover
        // surface pixels (the background stays where it was).
        let (w, h) = (400u32, 400u32);
        let mut silhouette = 0;
        for y in 0..h {
            for x in 0..w {
                let p = plain.get(x, y);
                let q = edged.get(x, y);
                if p == shade::BACKGROUND {
                    assert_eq!(
                        q,
                        shade::BACKGROUND,
                        "{input:?}: edge drawn outside at {x},{y}"
                    );
                    continue;
                }
                let next_to_background =
                    [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)]
                        .iter()
                        .any(|&(dx, dy)| {
                            let (u, v) = (i64::from(x) + dx, i64::from(y) + dy);
                            u >= 0
                                && v >= 0
                                && u < i64::from(w)
                                && v < i64::from(h)
                                && plain.get(u as u32, v as u32) == shade::BACKGROUND
                        });
                if next_to_background {
                    silhouette += 1;
                    assert_eq!(q, EDGE, "{input:?}: silhouette pixel {x},{y} not drawn");
                }
            }
        }
        assert!(
            silhouette > 400,
            "{input:?}: {silhouette} silhouette pixels"
        );
        // Creases: clearly more edge pixels than the silhouette alone.
        let edges = count(&edged, whole, EDGE);
        assert!(
            edges > silhouette + 300,
            "{input:?}: {edges} edge pixels, {silhouette} on the silhouette"
        );
        let axes = render(&input, &dir.path().join("axes.png"), &["--axes"]);
        for color in AXIS_COLORS {
            assert_eq!(
                count(&plain, whole, color),
                0,
                "{input:?}: {color:?} without --axes"
            );
            let corner = count(&axes, [0, 300, 100, 400], color);
            assert!(
                corner > 10,
                "{input:?}: axis {color:?} not in the lower-left corner"
            );
            assert_eq!(
                count(&axes, whole, color),
                corner,
                "{input:?}: axis {color:?} elsewhere"
            );
        }
    }
}

#[test]
fn sheet_bytes_do_not_depend_on_the_thread_count() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mesh = bracket_mesh(dir.path());
    for input in [fixture("examples/bracket.json"), mesh] {
        let mut files = Vec::new();
        for threads in ["1", "2", "3"] {
            let out = dir.path().join(format!("t{threads}.png"));
            ok(&[
                "--threads",
                threads,
                "render",
                path_str(&input),
                "-o",
                path_str(&out),
                "--size",
                "333x251",
                "--views",
                "4",
                "--edges",
                "--axes",
            ]);
            files.push(std::fs::read(&out).expect("png"));
        }
        assert!(
            files[0] == files[1] && files[1] == files[2],
            "{input:?}: bytes differ"
        );
    }
}

#[test]
fn bad_views_are_refused() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("x.png");
    let input = fixture("examples/bracket.json");
    for extra in [
        &["--views", "2"][..],
        &["--views", "4", "--size", "10x10"],
        &["--views", "4", "--size", "100000x100000"],
        &["--views", "4", "--view", "top"],
        &["--section", "z=0.1", "--edges"],
        &["--section", "z=0.1", "--views", "4"],
    ] {
        let mut args = vec!["render", path_str(&input), "-o", path_str(&out)];
        args.extend(extra);
        let o = run_cli(BIN, &args);
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
        assert!(!out.exists(), "{extra:?} wrote a file");
    }
}
