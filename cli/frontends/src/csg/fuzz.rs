//! A self-contained mutation fuzzer of the two tree readers: the `.csg` importer and the JSON
//! reader. Seeds are every `.csg` under `fixtures/csg/` and every `.json` tree under `fixtures/`;
//! each input is a seed (or an earlier accepted input) with 1–4 mutations: bit flips, deletions,
//! insertions of bytes and tokens, splices from other seeds, chunk duplication, number swaps and
//! deep nesting. Each input runs inside `catch_unwind`; a panic saves the input to
//! `fixtures/regressions/` (these files are replayed by `regressions_do_not_panic` in `tests.rs`).
//!
//! An abort that `catch_unwind` cannot see (stack overflow, out of memory) leaves the input in
//! `$TMPDIR/solidkit-fuzz-last.{csg,json}`; run under `ulimit -v` so memory blow-ups abort.
//!
//! Run (both readers in parallel, deterministic xorshift, seconds per reader):
//! `FUZZ_SECONDS=600 cargo test --release -p solidkit --bin solidkit fuzz_parsers -- --ignored --nocapture`

use super::{Facets, import};
use solidkit_tests::fixture;
use std::cell::RefCell;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Target {
    Csg,
    Json,
}

impl Target {
    fn ext(self) -> &'static str {
        match self {
            Target::Csg => "csg",
            Target::Json => "json",
        }
    }
    fn tokens(self) -> &'static [&'static str] {
        match self {
            Target::Csg => &[
                "group() {",
                "}",
                "{",
                "(",
                ")",
                "[",
                "]",
                ";",
                ",",
                "=",
                "-",
                ".",
                "e",
                "\"",
                "/*",
                "*/",
                "//",
                "\n",
                "undef",
                "true",
                "false",
                "$fn = 7",
                "$fn = 1e9",
                "$fa = 0",
                "$fs = 0",
                "$fn = -3",
                "r = -1",
                "r = 0",
                "h = 0",
                "center = true",
                "cube(1);",
                "sphere(1);",
                "cylinder(h = 1, r1 = 0, r2 = 0);",
                "circle(0);",
                "square([0, 0]);",
                "polygon([]);",
                "polyhedron(points = [], faces = []);",
                "hull() {",
                "union() {",
                "difference() {",
                "intersection() {",
                "linear_extrude(height = 1, twist = 1e9, scale = 0) {",
                "rotate_extrude(angle = 0) {",
                "rotate_extrude(angle = -1e308) {",
                "multmatrix([[0,0,0,0],[0,0,0,0],[0,0,0,0],[0,0,0,1]]) {",
                "multmatrix([[1,0,0]]) ",
                "color(\"red\") ",
                "render() ",
                "minkowski() {",
                "offset(r = -1) {",
                "offset(delta = 2, chamfer = true) {",
                "offset(r = 1e300) {",
                "offset(delta = -1e-300) {",
                "square([1e150, 1]);",
                "circle(1e120);",
                "paths = [[0, 1, 2], [5]]",
                "points = [[0, 0], [1, 0], [0, 1]]",
                "faces = [[0, 1, 2], [0, 0, 0], [9, 9, 9]]",
                "[[]]",
                "[",
                "1e308",
                "-1e308",
                "nan",
                "inf",
                "1e-320",
                "18446744073709551616",
                "4294967295",
                "-0",
            ],
            Target::Json => &[
                "{",
                "}",
                "[",
                "]",
                ":",
                ",",
                "\"",
                "\\",
                "\\u0000",
                "\\ud800",
                "null",
                "true",
                "false",
                "-",
                "0",
                "-0",
                "1e308",
                "-1e308",
                "1e-320",
                "1e999",
                "NaN",
                "18446744073709551616",
                "\"type\"",
                "\"children\"",
                "\"child\"",
                "\"radius\"",
                "\"size\"",
                "\"offset\"",
                "\"matrix\"",
                "\"root\"",
                "\"version\"",
                "{\"type\": \"sphere\", \"radius\": 1}",
                "{\"type\": \"union\", \"children\": []}",
                "{\"type\": \"mesh\", \"path\": \"/etc/passwd\"}",
                "[[]]",
                "\"\"",
                "0.0",
                "{\"type\": \"box\", \"size\": [0, 0, 0]}",
                "\u{e9}",
                "\u{1F600}",
            ],
        }
    }
    fn nest(self, depth: usize) -> (String, String) {
        match self {
            Target::Csg => (
                [
                    "group() {\n",
                    "union() {\n",
                    "multmatrix([[1,0,0,1],[0,1,0,0],[0,0,1,0],[0,0,0,1]]) ",
                ][depth % 3]
                    .repeat(depth),
                if depth % 3 == 2 {
                    String::new()
                } else {
                    "}\n".repeat(depth)
                },
            ),
            Target::Json => (
                "{\"type\": \"union\", \"children\": [".repeat(depth),
                "]}".repeat(depth),
            ),
        }
    }
    /// Runs the reader; `Ok(true)` when the input was accepted.
    fn run(self, input: &[u8]) -> bool {
        let text = String::from_utf8_lossy(input);
        match self {
            Target::Csg => {
                let mut ok = false;
                for facets in [Facets::Exact, Facets::OpenScad] {
                    if let Ok(s) = import(&text, facets) {
                        ok = true;
                        if s.validate().is_ok() {
                            let _ = s.bbox();
                        }
                    }
                }
                ok
            }
            Target::Json => match solidkit_kernel::json::from_str(&text) {
                Ok(s) => {
                    if s.validate().is_ok() {
                        let _ = s.bbox();
                        let _ = solidkit_kernel::json::to_string(&s);
                    }
                    true
                }
                Err(e) => {
                    let _ = e.to_string();
                    false
                }
            },
        }
    }
}

fn seeds(target: Target) -> Vec<Vec<u8>> {
    fn walk(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                if !p.ends_with("regressions") {
                    walk(&p, ext, out);
                }
            } else if p.extension().is_some_and(|x| x == ext) {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    let root = fixture(if target == Target::Csg { "csg" } else { "" });
    walk(&root, target.ext(), &mut files);
    files.sort();
    files
        .into_iter()
        .filter_map(|p| std::fs::read(p).ok())
        .collect()
}

fn mutate(rng: &mut XorShift, target: Target, base: &[u8], pool: &[Vec<u8>]) -> Vec<u8> {
    let mut v = base.to_vec();
    let n = 1 + rng.below(4);
    for _ in 0..n {
        let len = v.len();
        match rng.below(10) {
            0 if len > 0 => {
                let i = rng.below(len);
                v[i] ^= 1 << rng.below(8);
            }
            1 if len > 0 => {
                let i = rng.below(len);
                let k = (1 + rng.below(16)).min(len - i);
                v.drain(i..i + k);
            }
            2 => {
                let i = rng.below(len + 1);
                let k = 1 + rng.below(8);
                let bytes: Vec<u8> = (0..k).map(|_| rng.next() as u8).collect();
                v.splice(i..i, bytes);
            }
            3 | 4 => {
                let toks = target.tokens();
                let t = toks[rng.below(toks.len())].as_bytes();
                let i = rng.below(len + 1);
                v.splice(i..i, t.iter().copied());
            }
            5 => {
                let other = &pool[rng.below(pool.len())];
                if !other.is_empty() {
                    let a = rng.below(other.len());
                    let b = (a + 1 + rng.below(200)).min(other.len());
                    let i = rng.below(len + 1);
                    v.splice(i..i, other[a..b].iter().copied());
                }
            }
            6 if len > 0 => {
                let a = rng.below(len);
                let b = (a + 1 + rng.below(100)).min(len);
                let chunk = v[a..b].to_vec();
                let i = rng.below(len + 1);
                v.splice(i..i, chunk);
            }
            7 if len > 0 => {
                // Replace a run of digits by an extreme number.
                let i = rng.below(len);
                if let Some(s) = (i..len).find(|&j| v[j].is_ascii_digit()) {
                    let e = (s..len).find(|&j| !v[j].is_ascii_digit()).unwrap_or(len);
                    let nums = [
                        "0",
                        "1e308",
                        "1e-320",
                        "999999999999",
                        "18446744073709551616",
                        "1e9",
                        "3",
                        "-1",
                    ];
                    v.splice(s..e, nums[rng.below(nums.len())].bytes());
                }
            }
            8 => {
                let depth = [10, 100, 1000, 10_000, 100_000][rng.below(5)];
                let (open, close) = target.nest(depth);
                let mut w = open.into_bytes();
                w.extend_from_slice(&v);
                w.extend_from_slice(close.as_bytes());
                v = w;
            }
            _ if len > 0 => {
                // Truncate.
                v.truncate(rng.below(len));
            }
            _ => {}
        }
    }
    if v.len() > 4 << 20 {
        v.truncate(4 << 20);
    }
    v
}

thread_local! {
    static LAST_PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

fn fuzz(target: Target, seconds: u64, seed: u64) -> (u64, u64, Vec<String>) {
    let mut pool = seeds(target);
    assert!(!pool.is_empty(), "no seeds");
    let n_seeds = pool.len();
    let mut rng = XorShift(seed | 1);
    let deadline = Instant::now() + Duration::from_secs(seconds);
    let (mut tried, mut accepted) = (0u64, 0u64);
    let mut found: Vec<String> = Vec::new();
    let last = std::env::temp_dir().join(format!("solidkit-fuzz-last.{}", target.ext()));
    while Instant::now() < deadline {
        let base = pool[rng.below(pool.len())].clone();
        let input = mutate(&mut rng, target, &base, &pool);
        // Kept across an abort (stack overflow, OOM) that catch_unwind cannot see.
        {
            let _ = std::fs::write(&last, &input);
        }
        tried += 1;
        match catch_unwind(AssertUnwindSafe(|| target.run(&input))) {
            Ok(true) => {
                accepted += 1;
                if input.len() < 20_000 {
                    if pool.len() < n_seeds + 2000 {
                        pool.push(input);
                    } else {
                        let i = n_seeds + rng.below(2000);
                        pool[i] = input;
                    }
                }
            }
            Ok(false) => {}
            Err(_) => {
                let msg = LAST_PANIC.with(|m| m.borrow().clone());
                let key = msg.split(':').take(3).collect::<Vec<_>>().join(":");
                if found.iter().filter(|f| f.starts_with(&key)).count() < 3 {
                    let name = format!("{}-{:016x}.{}", target.ext(), rng.next(), target.ext());
                    let path = fixture("regressions").join(&name);
                    let _ = std::fs::create_dir_all(path.parent().expect("dir"));
                    std::fs::write(&path, &input).expect("save crash");
                    eprintln!(
                        "[{}] PANIC saved to {}: {msg}",
                        target.ext(),
                        path.display()
                    );
                    found.push(format!("{key} -> {name}"));
                }
            }
        }
    }
    let _ = std::fs::remove_file(&last);
    (tried, accepted, found)
}

#[test]
#[ignore = "long-running fuzzer: FUZZ_SECONDS=600 cargo test --release ... -- --ignored"]
fn fuzz_parsers() {
    let seconds: u64 = std::env::var("FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    let seed: u64 = std::env::var("FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x9E37_79B9_7F4A_7C15);
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|info| {
        let loc = info
            .location()
            .map(|l| format!("{}:{}", l.file(), l.line()))
            .unwrap_or_default();
        let payload = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        LAST_PANIC.with(|m| *m.borrow_mut() = format!("{loc}: {payload}"));
    }));
    let threads: Vec<_> = [Target::Csg, Target::Json]
        .into_iter()
        .map(|t| {
            std::thread::Builder::new()
                .stack_size(256 << 20)
                .spawn(move || fuzz(t, seconds, seed))
                .expect("spawn")
        })
        .collect();
    let results: Vec<_> = threads
        .into_iter()
        .map(|h| h.join().expect("fuzzer thread"))
        .collect();
    std::panic::set_hook(default_hook);
    let mut crashes = 0;
    for (t, (tried, accepted, found)) in ["csg", "json"].iter().zip(&results) {
        eprintln!(
            "fuzz {t}: {tried} inputs in {seconds} s, {accepted} accepted, {} panics",
            found.len()
        );
        for f in found {
            eprintln!("  {f}");
        }
        crashes += found.len();
    }
    assert_eq!(
        crashes, 0,
        "panics found; inputs saved in fixtures/regressions/"
    );
}
