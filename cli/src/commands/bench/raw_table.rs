//! The raw evaluation rates as a text table.

use super::case::median;
use super::raw::RawRow;
use super::table::{Table, si};

/// The raw rates as a table.
pub fn table(rows: &[RawRow]) -> Table {
    let mut t = Table::new(&[
        "measure",
        "model",
        "instructions",
        "count",
        "median s",
        "rate",
    ]);
    for r in rows {
        let mut sorted = r.times_s.clone();
        sorted.sort_by(f64::total_cmp);
        t.rows.push(vec![
            r.kind.to_string(),
            r.model.clone(),
            r.program_length.to_string(),
            r.count.to_string(),
            format!("{:.4}", median(&sorted)),
            format!("{} {}/s", si(r.rate_per_s), r.unit),
        ]);
    }
    t
}
