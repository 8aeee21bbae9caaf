//! Formula solids: the grammar (precedence, folding, located errors), the shape conformance
//! suite on formulas of every operation, and interval soundness on random formulas.

use super::parse::parse;
use super::{Expr, LIMIT};
use crate::primitive::Shape;
use crate::primitive::conformance::{Rng, check_shape};
use crate::{Aabb, Interval};
use glam::DVec3;

fn cube(h: f64) -> Aabb {
    Aabb::new(DVec3::splat(-h), DVec3::splat(h))
}

fn at(formula: &str, p: [f64; 3]) -> f64 {
    let e = Expr::new(formula, cube(100.0)).expect("parses");
    e.g(DVec3::from_array(p), &mut Vec::new())
}

#[test]
fn precedence_associativity_and_constants_follow_the_usual_rules() {
    let cases = [
        ("1 - 2 - 3", -4.0),
        ("8 / 4 / 2", 1.0),
        ("2 ^ 3 ^ 2", 512.0),
        ("-2 ^ 2", -4.0),
        ("(-2) ^ 2", 4.0),
        ("2 * -3", -6.0),
        ("+1 + -(-2)", 3.0),
        ("1 + 2 * 3 ^ 2", 19.0),
        ("min(1, max(2, 3)) + pow(2, 10)", 1025.0),
        ("sqrt(16) + abs(-2) + exp(0) + log(e)", 8.0),
        ("sin(pi / 2) + cos(0)", 2.0),
        ("2e1 + .5 + 1.5E-1", 20.65),
    ];
    for (f, v) in cases {
        assert!(
            (at(f, [0.0; 3]) - v).abs() < 1e-12,
            "{f} = {}",
            at(f, [0.0; 3])
        );
        // Everything constant folds into one instruction.
        assert_eq!(parse(f).expect("parses").len(), 1, "{f}");
    }
    assert_eq!(at("x - 2*y + z^3", [1.0, 2.0, 3.0]), 1.0 - 4.0 + 27.0);
    assert_eq!(at("x^-1", [4.0, 0.0, 0.0]), 0.25);
    assert_eq!(at("x^0.5", [9.0, 0.0, 0.0]), 3.0);
}

#[test]
fn operations_are_total_and_nan_is_outside() {
    assert_eq!(at("sqrt(x)", [-4.0, 0.0, 0.0]), 0.0);
    assert_eq!(at("x^0.5", [-4.0, 0.0, 0.0]), 0.0);
    assert!((at("log(x)", [-1.0, 0.0, 0.0]) - f64::MIN_POSITIVE.ln()).abs() < 1e-9);
    assert_eq!(at("x / x", [0.0, 0.0, 0.0]), LIMIT);
    assert_eq!(at("1 / x", [0.0, 0.0, 0.0]), LIMIT);
    assert_eq!(at("-exp(x)", [1000.0, 0.0, 0.0]), -LIMIT);
}

#[test]
fn bad_formulas_are_located_errors() {
    let cases = [
        ("x +", 4, "operand"),
        ("x y", 3, "operator"),
        ("foo(x)", 1, "unknown name 'foo'"),
        ("sin x", 1, "followed by '('"),
        ("min(x)", 1, "expected 2 argument"),
        ("sin(x, y)", 1, "expected 1 argument"),
        ("x ^ y", 3, "constant"),
        ("(x + 1", 0, "unclosed"),
        ("x + 1)", 6, "without a matching"),
        ("x # 2", 3, "unexpected character"),
        ("", 1, "operand"),
        ("1e400", 1, "finite"),
        ("sin()", 5, "arguments"),
        ("x, y", 2, "without a matching"),
        ("min(x, (y, z))", 10, "outside a function"),
    ];
    for (f, column, text) in cases {
        let e = parse(f).expect_err(f);
        assert_eq!(e.column, column, "{f}: {e}");
        assert!(e.message.contains(text), "{f}: {e}");
    }
    assert!(parse(&"x+".repeat(6000)).is_err());
    // Deep nesting is a loop, not a recursion.
    let deep = format!("{}x{}", "(".repeat(4000), ")".repeat(4000));
    assert_eq!(parse(&deep).expect("parses").len(), 1);
    let bad_box = Aabb::new(DVec3::ONE, DVec3::ZERO);
    assert!(Expr::new("x", bad_box).is_err());
    let infinite = Aabb::new(DVec3::splat(-1.0), DVec3::new(1.0, 1.0, f64::INFINITY));
    assert!(Expr::new("x", infinite).is_err());
}

#[test]
fn formulas_of_every_operation_conform() {
    let formulas = [
        "x*x + y*y + z*z - 1",
        "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)",
        "z - 0.5*sin(x*y)",
        "sqrt(x^2 + y^2) - 1 + abs(z) - 0.5",
        "max(abs(x), abs(y)) - exp(-z^2)",
        "min(x^3 - y, log(x*x + 0.1) + z)",
        "x^0.5 + y^-2 - 3",
        "1 / (x + 0.3) - y",
        "(x*y*z)^4 - 0.01",
    ];
    for f in formulas {
        let e = Expr::new(
            f,
            Aabb::new(DVec3::new(-1.5, -1.2, -1.0), DVec3::new(1.3, 1.5, 1.1)),
        )
        .expect("parses");
        check_shape(&e, 2.0);
    }
}

#[test]
fn the_lipschitz_bound_comes_from_interval_derivatives() {
    // |∇(x² + y² + z²)| ≤ 2·√3·h over [-h, h]³.
    let e = Expr::new("x*x + y*y + z*z - 1", cube(2.0)).expect("parses");
    assert!(
        (e.lipschitz() - 4.0 * 3f64.sqrt()).abs() < 1e-9,
        "{}",
        e.lipschitz()
    );
    // A plane is 1-Lipschitz.
    assert_eq!(
        Expr::new("z - 0.5", cube(2.0)).expect("parses").lipschitz(),
        1.0
    );
    // sqrt near 0: no bound from intervals.
    let s = Expr::new("sqrt(x*x + y*y + z*z) - 1", cube(2.0)).expect("parses");
    assert_eq!(s.lipschitz(), f64::INFINITY);
}

/// A random formula over x, y, z from every operation, `depth` levels deep.
fn random_formula(rng: &mut Rng, depth: usize) -> String {
    let pick = |rng: &mut Rng, n: usize| ((rng.next() * 0.5 + 0.5) * n as f64) as usize % n;
    // Build bottom-up with a list of subformulas (no recursion).
    let mut parts: Vec<String> = (0..1 << depth)
        .map(|_| match pick(rng, 5) {
            0 => "x".into(),
            1 => "y".into(),
            2 => "z".into(),
            3 => format!("{:.2}", rng.next() * 3.0),
            _ => format!("({:.2})", rng.next() * 0.5),
        })
        .collect();
    while parts.len() > 1 {
        let next = parts
            .chunks(2)
            .map(|c| {
                let (a, b) = (&c[0], &c[1]);
                match pick(rng, 16) {
                    0 => format!("({a} + {b})"),
                    1 => format!("({a} - {b})"),
                    2 => format!("({a} * {b})"),
                    3 => format!("({a} / {b})"),
                    4 => format!("min({a}, {b})"),
                    5 => format!("max({a}, {b})"),
                    6 => format!("sin({a})"),
                    7 => format!("cos({b})"),
                    8 => format!("exp({a})"),
                    9 => format!("log({a})"),
                    10 => format!("sqrt({b})"),
                    11 => format!("abs({a})"),
                    12 => format!("({a})^{}", pick(rng, 7) as i32 - 3),
                    13 => format!("pow({b}, 1.5)"),
                    14 => format!("(-{a})"),
                    _ => format!("({a})^-0.5"),
                }
            })
            .collect();
        parts = next;
    }
    parts.pop().unwrap_or_default()
}

#[test]
fn intervals_contain_every_value_of_random_formulas() {
    let bounds = cube(2.0);
    let seeds: u64 = std::env::var("SOLIDKIT_EXPR_SEEDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(4);
    for k in 0..3000 * seeds {
        let mut rng = Rng::new(11 + k);
        let f = random_formula(&mut rng, 4);
        let e = Expr::new(&f, bounds).expect("generated formulas parse");
        for _ in 0..10 {
            let c = rng.vec(2.5);
            let half = rng.vec(0.8).abs();
            let b = Aabb::new(c - half, c + half);
            let iv: Interval = e.interval(&b);
            for k in 0..12 {
                let t = DVec3::new(rng.next(), rng.next(), rng.next()) * 0.5 + 0.5;
                let t = if k < 8 {
                    DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64)
                } else {
                    t
                };
                let p = (b.min + (b.max - b.min) * t).clamp(b.min, b.max);
                let v = e.value(p);
                assert!(
                    iv.lo <= v && v <= iv.hi,
                    "{f}: {v} at {p} not in {iv:?} over {b:?}"
                );
                let mut out = [0.0f32];
                e.values_f32(&[p.x as f32], &[p.y as f32], &[p.z as f32], &mut out);
                let q = DVec3::new(p.x as f32 as f64, p.y as f32 as f64, p.z as f32 as f64);
                if b.contains(q) {
                    let w = out[0] as f64;
                    let slack = 1e-6 * (1.0 + w.abs());
                    assert!(
                        iv.lo - slack <= w && w <= iv.hi + slack,
                        "{f}: f32 {w} at {q}"
                    );
                }
            }
        }
    }
}
