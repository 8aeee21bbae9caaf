//! The benchmark cases as a text table, one row per case.

use super::case::CaseResult;
use super::table::{Table, si};

/// Column titles of the case table.
pub const COLUMNS: [&str; 18] = [
    "model",
    "method",
    "res",
    "threads",
    "median s",
    "min s",
    "max s",
    "report s",
    "total s",
    "self-int.",
    "triangles",
    "points/s",
    "peak MiB",
    "closed",
    "manifold",
    "shells",
    "genus",
    "vol err",
];

fn yes(b: bool) -> String {
    if b { "yes" } else { "NO" }.to_string()
}

/// The speed-up of `r` over the first result of the same model, resolution and method (the
/// first thread count of a scaling run): `meshing× / whole run×`.
fn speed_up(results: &[CaseResult], r: &CaseResult) -> String {
    let base = results
        .iter()
        .find(|b| b.model == r.model && b.resolution == r.resolution && b.method == r.method);
    match base {
        Some(b) => format!(
            "{:.2}x / {:.2}x",
            b.median_s() / r.median_s(),
            b.total_median_s() / r.total_median_s()
        ),
        None => "-".into(),
    }
}

/// The results as a table, one row per case; with `scaling`, a last column of speed-ups over
/// each case's first thread count.
pub fn table(results: &[CaseResult], scaling: bool) -> Table {
    let mut columns = COLUMNS.to_vec();
    if scaling {
        columns.push("speed-up");
    }
    let mut t = Table::new(&columns);
    for r in results {
        let c = &r.check;
        let genus = match (c.genus, c.expected_genus) {
            (Some(g), Some(want)) if g == want => format!("{g}"),
            (got, Some(want)) => format!("{} (want {want})", opt(got)),
            (got, None) => opt(got),
        };
        t.rows.push(vec![
            r.model.clone(),
            r.method.name().to_string(),
            r.resolution.to_string(),
            r.threads.to_string(),
            format!("{:.3}", r.median_s()),
            format!("{:.3}", r.min_s()),
            format!("{:.3}", r.max_s()),
            format!("{:.3}", r.report_median_s()),
            format!("{:.3}", r.total_median_s()),
            r.self_intersections_method
                .clone()
                .unwrap_or_else(|| "-".into()),
            r.triangles.to_string(),
            si(r.points_per_s()),
            r.peak_memory_bytes
                .map_or("-".into(), |b| format!("{:.0}", b as f64 / 1048576.0)),
            yes(c.closed),
            yes(c.manifold),
            c.shells.to_string(),
            genus,
            c.volume_error()
                .map_or("-".into(), |e| format!("{:+.3}%", 100.0 * e)),
        ]);
        if scaling {
            t.rows.last_mut().expect("a row").push(speed_up(results, r));
        }
    }
    t
}

fn opt(g: Option<i64>) -> String {
    g.map_or("-".into(), |g| g.to_string())
}
