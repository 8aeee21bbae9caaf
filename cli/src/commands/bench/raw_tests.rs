//! Tests of the raw evaluation rates and their table.

use super::raw::{RawSizes, run};
use super::raw_table::table;

#[test]
fn tiny_raw_run_has_every_row() {
    let sizes = RawSizes {
        points: 1000,
        many_points: 10,
        boxes: 100,
        many_resolution: 8,
    };
    let rows = run(&sizes, 1, &[]).expect("runs");
    let kinds: Vec<(&str, &str)> = rows.iter().map(|r| (r.kind, r.model.as_str())).collect();
    assert_eq!(
        kinds,
        [
            ("eval", "sphere"),
            ("eval", "gyroid-sphere"),
            ("eval", "many-8456"),
            ("interval", "sphere"),
            ("pruned-eval", "many-8456")
        ]
    );
    let text = table(&rows).render();
    assert_eq!(text.lines().count(), 1 + rows.len());
    assert!(text.lines().skip(1).all(|l| l.ends_with("/s")));
}

#[test]
fn models_select_rows_and_unknown_ones_are_refused() {
    let sizes = RawSizes {
        points: 1000,
        many_points: 10,
        boxes: 100,
        many_resolution: 8,
    };
    let rows = run(&sizes, 1, &["gyroid-sphere".into(), " sphere".into()]).expect("runs");
    let kinds: Vec<(&str, &str)> = rows.iter().map(|r| (r.kind, r.model.as_str())).collect();
    assert_eq!(
        kinds,
        [
            ("eval", "sphere"),
            ("eval", "gyroid-sphere"),
            ("interval", "sphere")
        ]
    );
    let err = run(&sizes, 1, &["menger-4".into()])
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("menger-4") && err.contains("many-8456"),
        "{err}"
    );
}
