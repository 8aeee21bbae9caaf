//! The summary `gen` prints (the self-checks that decide its exit code are
//! `solidkit_meshing::suites::Manifest::failures`).

use solidkit_meshing::suites::Manifest;
use std::fmt::Write;

/// One line per solid: triangles, shells, genus (measured / true), volume error.
pub fn summary(m: &Manifest) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<24} {:>9} {:>7} {:>13} {:>12}",
        "solid", "triangles", "shells", "genus", "volume err"
    );
    for r in &m.solids {
        let genus = |g: Option<i64>| g.map_or("-".to_owned(), |g| g.to_string());
        let err = r
            .error
            .volume_relative
            .map_or("-".to_owned(), |e| format!("{e:+.2e}"));
        let _ = writeln!(
            s,
            "{:<24} {:>9} {:>7} {:>13} {:>12}",
            r.name,
            r.mesh.faces,
            r.mesh.shells,
            format!("{} / {}", genus(r.mesh.genus), genus(r.truth.genus)),
            err
        );
    }
    s
}
