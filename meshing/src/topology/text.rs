//! Human-readable rendering of a [`TopologyReport`]: aligned `key: value` lines, then the
//! offending items when there are any.

use std::fmt::{self, Display, Write as _};

use super::TopologyReport;

/// Width of the key column, colon included.
const KEY_WIDTH: usize = 24;

impl TopologyReport {
    /// A multi-line report: one aligned `key: value` line per measure, then one line per kind of
    /// offending item listing the examples (only when there are offenders).
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        for (key, value) in self.summary_lines() {
            line(&mut out, key, value);
        }
        for (key, count, items) in self.offender_lines() {
            if count > 0 {
                let more = if count > items.len() { " ..." } else { "" };
                line(&mut out, key, format!("{}{more}", items.join(" ")));
            }
        }
        out
    }

    /// The measure lines.
    fn summary_lines(&self) -> Vec<(&'static str, String)> {
        let [lo, hi] = self.bbox;
        vec![
            ("vertices", self.vertices.to_string()),
            ("edges", self.edges.to_string()),
            ("faces", self.faces.to_string()),
            (
                "euler characteristic",
                self.euler_characteristic.to_string(),
            ),
            ("shells", self.shells.to_string()),
            ("genus", genus_text(self.genus)),
            ("genus per shell", genus_list(&self.genus_per_shell)),
            ("closed", yes_no(self.closed)),
            ("manifold", yes_no(self.manifold)),
            ("oriented", yes_no(self.oriented)),
            ("closed manifold", yes_no(self.is_closed_manifold())),
            ("boundary edges", self.boundary_edges.to_string()),
            ("non-manifold edges", self.non_manifold_edges.to_string()),
            (
                "non-manifold vertices",
                self.non_manifold_vertices.to_string(),
            ),
            ("inconsistent edges", self.inconsistent_edges.to_string()),
            ("degenerate faces", self.degenerate_faces.to_string()),
            (
                "self-intersections",
                match (self.self_intersections, self.self_intersections_method) {
                    (None, _) => "- (not checked)".to_string(),
                    (Some(n), Some(m)) => format!("{n} ({})", m.name()),
                    (Some(n), None) => n.to_string(),
                },
            ),
            (
                "unreferenced vertices",
                self.unreferenced_vertices.to_string(),
            ),
            ("volume", self.volume.to_string()),
            ("area", self.area.to_string()),
            ("bbox min", point(lo)),
            ("bbox max", point(hi)),
        ]
    }

    /// The offender lines: key, total count and rendered examples.
    fn offender_lines(&self) -> [(&'static str, usize, Vec<String>); 6] {
        let ex = &self.examples;
        [
            (
                "boundary edges at",
                self.boundary_edges,
                edges(&ex.boundary_edges),
            ),
            (
                "non-manifold edges at",
                self.non_manifold_edges,
                edges(&ex.non_manifold_edges),
            ),
            (
                "non-manifold vertices",
                self.non_manifold_vertices,
                items(&ex.non_manifold_vertices),
            ),
            (
                "inconsistent edges at",
                self.inconsistent_edges,
                edges(&ex.inconsistent_edges),
            ),
            (
                "degenerate faces at",
                self.degenerate_faces,
                items(&ex.degenerate_faces),
            ),
            (
                "intersecting faces",
                self.self_intersections.unwrap_or(0),
                edges(&ex.self_intersections),
            ),
        ]
    }
}

impl Display for TopologyReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

/// Appends one aligned `key: value` line.
fn line(out: &mut String, key: &str, value: String) {
    let key = format!("{key}:");
    // Writing to a String cannot fail.
    let _ = writeln!(out, "{key:<KEY_WIDTH$}{value}");
}

/// `yes` or `no`.
fn yes_no(b: bool) -> String {
    if b { "yes" } else { "no" }.to_string()
}

/// A genus, `-` for none.
fn genus_text(g: Option<i64>) -> String {
    g.map_or_else(|| "-".to_string(), |g| g.to_string())
}

/// `[g0, g1, ...]`.
fn genus_list(gs: &[Option<i64>]) -> String {
    let parts: Vec<String> = gs.iter().map(|&g| genus_text(g)).collect();
    format!("[{}]", parts.join(", "))
}

/// `x y z`.
fn point(p: [f64; 3]) -> String {
    format!("{} {} {}", p[0], p[1], p[2])
}

/// Edges (or face pairs) as `a-b`.
fn edges(list: &[[u32; 2]]) -> Vec<String> {
    list.iter().map(|[a, b]| format!("{a}-{b}")).collect()
}

/// Indices as text.
fn items(list: &[u32]) -> Vec<String> {
    list.iter().map(u32::to_string).collect()
}
