//! Tests of one benchmark case and its table row.

use super::case::{CaseResult, Check, median, run};
use super::case_table::{COLUMNS, table};
use crate::args::Method;
use solidkit_kernel::models::Model;

#[test]
fn a_tiny_case_fills_one_row_of_every_column() {
    let model = Model::by_name("sphere").expect("model");
    let r = run(&model, 16, 2, Method::Mc, false).expect("runs");
    assert_eq!(r.times_s.len(), 2);
    assert_eq!(r.report_times_s.len(), 2);
    assert!(r.total_median_s() > r.median_s() && r.report_median_s() > 0.0);
    assert_eq!(r.self_intersections_method.as_deref(), Some("construction"));
    assert!(r.triangles > 0 && r.samples_evaluated > 0);
    assert!(r.check.passed(), "{:?}", r.check);
    assert!(r.check.volume_error().is_some());
    let text = table(std::slice::from_ref(&r), false).render();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2);
    for (line, first) in lines.iter().zip(["model", "sphere"]) {
        let cells: Vec<&str> = line.split("  ").filter(|c| !c.trim().is_empty()).collect();
        assert_eq!(cells.len(), COLUMNS.len(), "{line}");
        assert_eq!(cells[0].trim(), first);
    }
    // The child-process protocol: the JSON line reads back to the same result.
    let line = serde_json::to_string(&r).expect("json");
    assert_eq!(serde_json::from_str::<CaseResult>(&line).expect("parse"), r);
    let v = r.to_json();
    for key in [
        "median_s",
        "report_median_s",
        "total_median_s",
        "points_per_s",
        "check_passed",
        "triangles",
        "check",
    ] {
        assert!(v.get(key).is_some(), "{key}");
    }
}

#[test]
fn scaling_rows_give_the_speed_up_over_the_first_thread_count() {
    let model = Model::by_name("sphere").expect("model");
    let one = run(&model, 16, 1, Method::Mc, false).expect("runs");
    let mut two = one.clone();
    two.threads = 2;
    two.times_s = one.times_s.iter().map(|t| t / 2.0).collect();
    two.report_times_s = one.report_times_s.iter().map(|t| t / 2.0).collect();
    let text = table(&[one, two], true).render();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3);
    assert!(lines[0].trim_end().ends_with("speed-up"), "{}", lines[0]);
    assert!(
        lines[1].trim_end().ends_with("1.00x / 1.00x"),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].trim_end().ends_with("2.00x / 2.00x"),
        "{}",
        lines[2]
    );
}

#[test]
fn dual_contouring_cases_run_and_pass_their_check() {
    let model = Model::by_name("sphere").expect("model");
    let r = run(&model, 16, 1, Method::Dc, false).expect("runs");
    assert_eq!(r.method, Method::Dc);
    assert!(r.check.passed(), "{:?}", r.check);
    assert!(r.check.volume_error().is_some_and(|e| e.abs() < 0.02));
    let line = serde_json::to_string(&r).expect("json");
    assert!(line.contains("\"method\":\"dc\""), "{line}");
    assert_eq!(r.self_intersections_method.as_deref(), Some("construction"));
}

#[test]
fn a_wrong_genus_fails_the_check() {
    let c = Check {
        closed: true,
        manifold: true,
        shells: 1,
        genus: Some(4),
        expected_genus: Some(5),
        volume: 1.0,
        expected_volume: None,
    };
    assert!(!c.passed());
    assert!(c.volume_error().is_none());
}

#[test]
fn medians() {
    assert_eq!(median(&[1.0, 2.0, 9.0]), 2.0);
    assert_eq!(median(&[1.0, 2.0, 4.0, 9.0]), 3.0);
    assert!(median(&[]).is_nan());
}
