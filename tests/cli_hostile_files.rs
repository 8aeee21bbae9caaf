//! Hostile files through the real binary (issue 15, "Files" and the reading budgets): the files a
//! tree or script names stay inside its folder unless `--allow-path` says otherwise (absolute
//! paths, `..`, symbolic links), only regular files within the size cap are read (FIFOs, devices,
//! directories fail fast), PNG height maps have dimension limits, errors never quote a foreign
//! file's content nor print control characters, and JSON duplicate keys and raw control
//! characters are located errors. Every failure is exit 2 with one line on stderr, within 2 s;
//! 40 000 coincident triangles are checked and meshed within the same budget.

use solidkit_tests::{fixture, path_str};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

const TETRA_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const SECRET: &str = "root:x:0:0:root:/root:/bin/bash\nsecret-token-4711\n";

/// Runs the binary with a 2-second budget (killed after 10 s so a hang fails the test rather
/// than blocking it).
fn solidkit(args: &[&str]) -> Output {
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_solidkit"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run solidkit");
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            panic!("solidkit {args:?} hung");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    let out = child.wait_with_output().expect("output");
    assert!(
        start.elapsed() < Duration::from_secs(2),
        "solidkit {args:?} took {:?}",
        start.elapsed()
    );
    out
}

/// Asserts exit 2 with one stderr line containing every phrase, none of the secret's content
/// and no control character; returns the line.
fn fails(args: &[&str], phrases: &[&str]) -> String {
    let o = solidkit(args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    for phrase in phrases {
        assert!(
            err.contains(phrase),
            "{args:?}: missing '{phrase}' in {err}"
        );
    }
    for leaked in ["root:x", "/bin/bash", "secret-token"] {
        assert!(!err.contains(leaked), "{args:?}: leaked '{leaked}': {err}");
    }
    let line = err.trim_end_matches('\n');
    assert!(
        !line.chars().any(char::is_control),
        "{args:?}: control character in {line:?}"
    );
    line.to_owned()
}

fn succeeds(args: &[&str]) {
    let o = solidkit(args);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// `DIR/tree/` holding `tet.obj` and `map.png`; `DIR/outside/` holding the same files and a
/// secret; the tree folder links to the outside ones.
struct Layout {
    _dir: tempfile::TempDir,
    root: PathBuf,
}

impl Layout {
    fn new() -> Self {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path().to_path_buf();
        let png = std::fs::read(fixture("heightfields/bump16.png")).unwrap();
        for sub in ["tree", "outside"] {
            std::fs::create_dir(root.join(sub)).unwrap();
            std::fs::write(root.join(sub).join("tet.obj"), TETRA_OBJ).unwrap();
            std::fs::write(root.join(sub).join("map.png"), &png).unwrap();
        }
        std::fs::write(root.join("outside/secret.txt"), SECRET).unwrap();
        std::fs::write(root.join("top.obj"), TETRA_OBJ).unwrap();
        std::fs::create_dir(root.join("tree/sub")).unwrap();
        #[cfg(unix)]
        {
            use std::os::unix::fs::symlink;
            symlink(root.join("outside/tet.obj"), root.join("tree/link.obj")).unwrap();
            symlink(root.join("outside/map.png"), root.join("tree/link.png")).unwrap();
            symlink(root.join("outside"), root.join("tree/out")).unwrap();
            symlink(root.join("outside/secret.txt"), root.join("tree/x.off")).unwrap();
            symlink("tet.obj", root.join("tree/inner.obj")).unwrap();
        }
        Self { _dir: dir, root }
    }

    fn path(&self, rel: &str) -> PathBuf {
        self.root.join(rel)
    }

    /// Writes `tree/NAME` with `text` and returns its path.
    fn tree(&self, name: &str, text: &str) -> PathBuf {
        let p = self.path("tree").join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    fn mesh_tree(&self, name: &str, path: &str) -> PathBuf {
        let node = format!(
            r#"{{"type": "difference", "children": [{{"type": "mesh", "path": {path:?}}}, {{"type": "sphere", "radius": 0.1}}]}}"#
        );
        self.tree(name, &node)
    }

    fn png_tree(&self, name: &str, path: &str) -> PathBuf {
        self.tree(
            name,
            &format!(
                r#"{{"type": "heightfield", "min": [0, 0], "max": [1, 1], "base": 0,
                    "png": {path:?}, "heights": [0.1, 0.5]}}"#
            ),
        )
    }
}

fn mesh_args(tree: &Path) -> Vec<&str> {
    vec!["mesh", path_str(tree), "--resolution", "12"]
}

#[test]
fn files_inside_the_tree_folder_are_read() {
    let l = Layout::new();
    for (name, path) in [
        ("a.json", "tet.obj"),
        ("b.json", "./tet.obj"),
        ("c.json", "sub/../tet.obj"),
    ] {
        succeeds(&mesh_args(&l.mesh_tree(name, path)));
    }
    #[cfg(unix)]
    succeeds(&mesh_args(&l.mesh_tree("d.json", "inner.obj")));
    succeeds(&mesh_args(&l.png_tree("p.json", "map.png")));
    // A Rhai script's files are relative to the script's folder too.
    let script = l.tree(
        "s.rhai",
        r#"node(#{type: "mesh", path: "tet.obj"}).union(node(#{type: "heightfield",
            min: [0, 0], max: [1, 1], base: 0, png: "map.png", heights: [0.1, 0.5]}))"#,
    );
    succeeds(&mesh_args(&script));
    // Also when the tree is named relative to the working directory.
    let o = Command::new(env!("CARGO_BIN_EXE_solidkit"))
        .args(["mesh", "a.json", "--resolution", "12"])
        .current_dir(l.path("tree"))
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn absolute_paths_and_dot_dot_are_refused_without_allow_path() {
    let l = Layout::new();
    let abs_mesh = l.path("outside/tet.obj");
    let abs_png = l.path("outside/map.png");
    let cases = [
        (
            l.mesh_tree("a.json", path_str(&abs_mesh)),
            "absolute paths are not allowed",
        ),
        (
            l.mesh_tree("b.json", "../outside/tet.obj"),
            "outside the folder of the tree",
        ),
        (
            l.mesh_tree("c.json", "../nothing/here.obj"),
            "outside the folder of the tree",
        ),
        (
            l.png_tree("d.json", path_str(&abs_png)),
            "absolute paths are not allowed",
        ),
        (
            l.png_tree("e.json", "../outside/map.png"),
            "outside the folder of the tree",
        ),
        (
            l.mesh_tree("f.json", "/etc/passwd.off"),
            "absolute paths are not allowed",
        ),
    ];
    for (tree, phrase) in &cases {
        let line = fails(&mesh_args(tree), &[phrase, "--allow-path"]);
        // Located at the node's key.
        let name = tree.file_name().unwrap().to_str().unwrap();
        let key = if line.contains("map.png") {
            "png: "
        } else {
            "path: "
        };
        assert!(
            line.contains(&format!("{name}:")) && line.contains(key),
            "{line}"
        );
    }
    // `convert` reads trees the same way.
    let out = l.path("out.json");
    fails(
        &["convert", path_str(&cases[1].0), "-o", path_str(&out)],
        &["outside the folder of the tree"],
    );
    assert!(!out.exists());
    // Rhai scripts too.
    let script = l.tree(
        "s.rhai",
        r#"node(#{type: "mesh", path: "../outside/tet.obj"})"#,
    );
    fails(&mesh_args(&script), &["outside the folder of the tree"]);
    // With the folder allowed, every one of them is read (the missing file is then just missing).
    let allow = path_str(&l.root).to_owned();
    for (tree, _) in &cases[..5] {
        let mut args = mesh_args(tree);
        args.extend(["--allow-path", &allow]);
        if tree.ends_with("c.json") {
            fails(&args, &["No such file"]);
        } else {
            succeeds(&args);
        }
    }
    let mut args = mesh_args(&script);
    args.extend(["--allow-path", &allow]);
    succeeds(&args);
    // A bad --allow-path is an error of its own.
    let mut args = mesh_args(&cases[0].0);
    args.extend(["--allow-path", "/no/such/dir"]);
    fails(&args, &["--allow-path", "/no/such/dir"]);
}

#[cfg(unix)]
#[test]
fn symbolic_links_out_of_the_folder_are_refused() {
    let l = Layout::new();
    let cases = [
        l.mesh_tree("a.json", "link.obj"),
        l.mesh_tree("b.json", "out/tet.obj"),
        l.png_tree("c.json", "link.png"),
        l.png_tree("d.json", "out/map.png"),
        // `out/..` is the folder above the tree once the link is followed.
        l.mesh_tree("e.json", "out/../top.obj"),
    ];
    for tree in &cases {
        fails(
            &mesh_args(tree),
            &["outside the folder of the tree", "symbolic link"],
        );
    }
    // Allowing the target folder (not the tree's parent) is enough.
    let allow = l.path("outside");
    for tree in &cases[..4] {
        let mut args = mesh_args(tree);
        args.extend(["--allow-path", path_str(&allow)]);
        succeeds(&args);
    }
}

#[cfg(unix)]
#[test]
fn only_regular_files_are_read() {
    let l = Layout::new();
    let fifo = l.path("tree/fifo.stl");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    fails(&["check", path_str(&fifo)], &["not a regular file", "FIFO"]);
    fails(
        &[
            "compare",
            path_str(&fifo),
            path_str(&l.path("tree/tet.obj")),
        ],
        &["not a regular file"],
    );
    std::fs::create_dir(l.path("tree/dir.stl")).unwrap();
    fails(
        &["check", path_str(&l.path("tree/dir.stl"))],
        &["not a regular file", "directory"],
    );
    // The tree itself.
    let fifo_tree = l.path("tree/fifo.json");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo_tree)
            .status()
            .unwrap()
            .success()
    );
    fails(&mesh_args(&fifo_tree), &["not a regular file"]);
    // Files named by the tree: a FIFO, /dev/zero through a link, /dev/urandom as a PNG.
    std::os::unix::fs::symlink("/dev/zero", l.path("tree/zero.stl")).unwrap();
    std::os::unix::fs::symlink("/dev/urandom", l.path("tree/random.png")).unwrap();
    let trees = [
        l.mesh_tree("a.json", "fifo.stl"),
        l.mesh_tree("b.json", "zero.stl"),
        l.png_tree("c.json", "random.png"),
        l.mesh_tree("d.json", "dir.stl"),
    ];
    // Refused as outside the folder first…
    fails(&mesh_args(&trees[1]), &["outside the folder of the tree"]);
    // …and as devices even where the folder is allowed.
    for tree in &trees {
        let mut args = mesh_args(tree);
        args.extend(["--allow-path", "/dev"]);
        fails(&args, &["not a regular file"]);
    }
}

#[test]
fn files_over_the_size_cap_are_refused_before_reading() {
    let l = Layout::new();
    let big = l.path("tree/big.stl");
    // Sparse: 1 GiB + 1 byte without writing them.
    let f = std::fs::File::create(&big).unwrap();
    f.set_len((1 << 30) + 1).unwrap();
    drop(f);
    fails(
        &["check", path_str(&big)],
        &[
            "file too large",
            "1073741825 bytes",
            "limit is 1073741824 bytes",
        ],
    );
    fails(
        &mesh_args(&l.mesh_tree("a.json", "big.stl")),
        &["file too large"],
    );
    let f = std::fs::File::create(l.path("tree/big.json")).unwrap();
    f.set_len((1 << 30) + 1).unwrap();
    fails(&mesh_args(&l.path("tree/big.json")), &["file too large"]);
}

/// A PNG that declares `width × height` 8-bit grayscale pixels but carries almost no data.
fn png_declaring(width: u32, height: u32) -> Vec<u8> {
    fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
        out.extend((data.len() as u32).to_be_bytes());
        let mut typed = kind.to_vec();
        typed.extend(data);
        out.extend(&typed);
        out.extend(solidkit_meshing::io::crc32(&typed).to_be_bytes());
    }
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut ihdr = Vec::new();
    ihdr.extend(width.to_be_bytes());
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 0, 0, 0, 0]);
    chunk(&mut out, b"IHDR", &ihdr);
    // zlib header and one stored block of 16 zero bytes.
    let mut idat = vec![0x78, 0x01, 0x01, 16, 0, !16, 0xff];
    idat.extend([0u8; 16]);
    chunk(&mut out, b"IDAT", &idat);
    chunk(&mut out, b"IEND", &[]);
    out
}

#[test]
fn png_dimensions_are_limited_before_decoding() {
    let l = Layout::new();
    std::fs::write(l.path("tree/bomb.png"), png_declaring(30_000, 30_000)).unwrap();
    std::fs::write(l.path("tree/wide.png"), png_declaring(100_000, 2)).unwrap();
    for (name, png, size) in [
        ("a.json", "bomb.png", "30000 × 30000"),
        ("b.json", "wide.png", "100000 × 2"),
    ] {
        let line = fails(&mesh_args(&l.png_tree(name, png)), &["too large", size]);
        assert!(
            line.contains(&format!("{name}:2:")) && line.contains("png:"),
            "{line}"
        );
    }
}

#[cfg(unix)]
#[test]
fn errors_never_quote_foreign_content() {
    let l = Layout::new();
    // tree/x.off links to a password-like file outside; allowed, it is read but not quoted.
    let tree = l.mesh_tree("a.json", "x.off");
    fails(&mesh_args(&tree), &["outside the folder of the tree"]);
    let mut args = mesh_args(&tree);
    let allow = l.path("outside");
    args.extend(["--allow-path", path_str(&allow)]);
    fails(&args, &["x.off", "not an OFF file"]);
    for ext in ["stl", "ply"] {
        let link = l.path(&format!("tree/x.{ext}"));
        std::os::unix::fs::symlink(l.path("outside/secret.txt"), &link).unwrap();
        fails(&["check", path_str(&link)], &[]);
    }
    // OBJ ignores lines it does not know: an empty mesh (exit 1), nothing quoted.
    let link = l.path("tree/x.obj");
    std::os::unix::fs::symlink(l.path("outside/secret.txt"), &link).unwrap();
    let o = solidkit(&["check", path_str(&link)]);
    assert_eq!(o.status.code(), Some(1));
    let all = [o.stdout, o.stderr].concat();
    assert!(!String::from_utf8_lossy(&all).contains("root"));
}

#[test]
fn control_characters_in_messages_are_escaped() {
    let l = Layout::new();
    // A path with ESC, CR and NUL (JSON escapes) in a tree.
    let tree = l.tree(
        "a.json",
        r#"{"type": "mesh", "path": "\u001b[2J\r\u0000evil.stl"}"#,
    );
    let line = fails(&mesh_args(&tree), &["\\u{1b}[2J\\r\\0evil.stl"]);
    assert!(!line.contains('\u{1b}'), "{line:?}");
    // A file name with ESC on the command line.
    let name = l.path("tree/\u{1b}]0;title\u{7}.stl");
    std::fs::write(&name, "not an stl").unwrap();
    fails(&["check", path_str(&name)], &["\\u{1b}]0;title\\u{7}.stl"]);
    // A script's own output to standard error.
    let script = l.tree("p.rhai", "print(\"a\\x1b[2Jb\\rc\"); sphere(1)");
    let o = solidkit(&mesh_args(&script));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("a\\u{1b}[2Jb\\rc"), "{err:?}");
    assert!(!err.contains('\u{1b}') && !err.contains('\r'), "{err:?}");
}

#[test]
fn json_duplicate_keys_and_raw_control_characters_are_located_errors() {
    let l = Layout::new();
    let dup = l.tree(
        "dup.json",
        "{\"type\": \"sphere\",\n \"radius\": 1, \"radius\": 2}",
    );
    fails(
        &mesh_args(&dup),
        &["dup.json:2:15:", "duplicate key \"radius\""],
    );
    let raw = l.tree("raw.json", "{\"type\": \"sph\u{1b}ere\", \"radius\": 1}");
    fails(
        &mesh_args(&raw),
        &["raw.json:1:14:", "control character in string"],
    );
    let nul = l.tree(
        "nul.json",
        "{\"comment\": \"a\0b\", \"type\": \"sphere\", \"radius\": 1}",
    );
    fails(
        &mesh_args(&nul),
        &["nul.json:1:15:", "control character in string"],
    );
}

#[test]
fn csg_import_and_surface_read_no_files() {
    let l = Layout::new();
    for (name, text) in [
        ("a.csg", "import(file = \"/etc/passwd.stl\");"),
        ("b.csg", "surface(file = \"../outside/map.png\");"),
    ] {
        let csg = l.tree(name, text);
        fails(&mesh_args(&csg), &[name]);
    }
}

/// 40 000 coincident triangles (a 2 MB binary STL): `check` counts all C(40000, 2) intersecting
/// pairs and a `mesh` node on the file meshes, each within the 2 s budget.
#[test]
fn coincident_triangles_stay_fast() {
    let l = Layout::new();
    let mut stl = vec![0u8; 80];
    stl.extend(40_000u32.to_le_bytes());
    let floats: [f32; 12] = [0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0.];
    for _ in 0..40_000 {
        stl.extend(floats.iter().flat_map(|f| f.to_le_bytes()));
        stl.extend([0, 0]);
    }
    let file = l.path("tree/coincident.stl");
    std::fs::write(&file, &stl).unwrap();
    let o = solidkit(&["check", path_str(&file), "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let report: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(report["self_intersections"], 40_000u64 * 39_999 / 2);
    let tree = l.tree(
        "c.json",
        r#"{"type": "union", "children": [{"type": "mesh", "path": "coincident.stl"},
            {"type": "sphere", "radius": 0.2}]}"#,
    );
    succeeds(&["mesh", path_str(&tree), "--resolution", "128"]);
}

#[test]
fn an_output_in_a_missing_folder_is_named_once_with_its_cause() {
    let l = Layout::new();
    let tree = l.tree("s.json", r#"{"type": "sphere", "radius": 1}"#);
    let out = l.path("no-such-folder").join("x.stl");
    for json in [false, true] {
        let mut args = mesh_args(&tree);
        args.extend(["-o", path_str(&out)]);
        if json {
            args.push("--json");
        }
        let line = fails(&args, &["no-such-folder", "x.stl", "No such file"]);
        // The I/O error names its path and quotes the system's message; the cause chain does
        // not repeat it.
        assert_eq!(line.matches("No such file").count(), 1, "{line}");
    }
}
