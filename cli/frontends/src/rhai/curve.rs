//! Curves in scripts: `curve(map)` reads a curve object of the JSON format (every kind:
//! `bezier`, `hermite`, `bspline`, `nurbs`, `interpolating`, `cubic_through`, `composite`,
//! `formula`) with the kernel's reader, and its methods evaluate it: `point(u)`, `derivative(u)`,
//! `second_derivative(u)`, `tangent(u)` (unit), `domain()`, `length()`, `is_closed()`,
//! `split(u)` (the de Casteljau halves of the Bézier piece holding `u`), `polyline(chord_error)`
//! and `samples(n)` (arrays of `[x, y, z]` points).

use super::node;
use super::shape::{Fallible, fail, num};
use glam::DVec3;
use rhai::{Array, Dynamic, Engine, Map};
use solidkit_kernel::curve::{BezierPiece, Parametric, flatten::uniform_params};
use std::sync::Arc;

/// A curve as scripts see it (type name `Curve`).
#[derive(Debug, Clone)]
pub struct ScriptCurve(pub(super) Arc<Parametric>);

fn point(p: DVec3) -> Dynamic {
    Dynamic::from_array(vec![p.x.into(), p.y.into(), p.z.into()])
}

fn points(ps: impl Iterator<Item = DVec3>) -> Array {
    ps.map(point).collect()
}

impl ScriptCurve {
    /// The parameter `u` checked against the domain.
    fn param(&self, u: &Dynamic, what: &str) -> Fallible<f64> {
        let u = num(u, what)?;
        let (t0, t1) = self.0.domain();
        if u.is_finite() && u >= t0 && u <= t1 {
            Ok(u)
        } else {
            fail(format!(
                "{what}: {u} is outside the curve's domain [{t0}, {t1}]"
            ))
        }
    }
}

fn piece_map(p: &BezierPiece) -> Dynamic {
    let mut m = Map::new();
    m.insert("points".into(), points(p.projected()).into());
    let weights: Array = p.points.iter().map(|q| Dynamic::from(q.w)).collect();
    m.insert("weights".into(), weights.into());
    m.insert(
        "interval".into(),
        Dynamic::from_array(vec![p.t0.into(), p.t1.into()]),
    );
    Dynamic::from_map(m)
}

/// Registers `curve(map)` and the methods of `Curve`.
pub(super) fn register(engine: &mut Engine) {
    engine.register_type_with_name::<ScriptCurve>("Curve");
    engine.register_fn("to_string", |c: &mut ScriptCurve| {
        let (t0, t1) = c.0.domain();
        format!("Curve({}, [{t0}, {t1}])", c.0.name())
    });
    engine.register_fn("curve", |m: Map| -> Fallible<ScriptCurve> {
        super::check_deadline()?;
        let text = node::json_text(m, "curve")?;
        match solidkit_kernel::json::curve_from_str(&text) {
            Ok(c) => Ok(ScriptCurve(Arc::new(c))),
            Err(solidkit_kernel::KernelError::Json { message, .. }) => {
                fail(format!("curve: {message}"))
            }
            Err(e) => fail(format!("curve: {e}")),
        }
    });
    engine.register_fn(
        "point",
        |c: &mut ScriptCurve, u: Dynamic| -> Fallible<Dynamic> {
            Ok(point(c.0.point(c.param(&u, "point")?)))
        },
    );
    engine.register_fn(
        "derivative",
        |c: &mut ScriptCurve, u: Dynamic| -> Fallible<Dynamic> {
            Ok(point(c.0.jet(c.param(&u, "derivative")?).d1))
        },
    );
    engine.register_fn(
        "second_derivative",
        |c: &mut ScriptCurve, u: Dynamic| -> Fallible<Dynamic> {
            Ok(point(c.0.jet(c.param(&u, "second_derivative")?).d2))
        },
    );
    engine.register_fn(
        "tangent",
        |c: &mut ScriptCurve, u: Dynamic| -> Fallible<Dynamic> {
            Ok(point(
                c.0.jet(c.param(&u, "tangent")?).d1.normalize_or_zero(),
            ))
        },
    );
    engine.register_fn("domain", |c: &mut ScriptCurve| -> Array {
        let (t0, t1) = c.0.domain();
        vec![t0.into(), t1.into()]
    });
    engine.register_fn("length", |c: &mut ScriptCurve| c.0.arc_length());
    engine.register_fn("is_closed", |c: &mut ScriptCurve| c.0.is_closed());
    engine.register_fn(
        "split",
        |c: &mut ScriptCurve, u: Dynamic| -> Fallible<Map> {
            let u = c.param(&u, "split")?;
            let Some(s) = c.0.split(u) else {
                return fail("split: a formula curve has no control points to split");
            };
            let mut m = Map::new();
            m.insert("left".into(), piece_map(&s.left));
            m.insert("right".into(), piece_map(&s.right));
            m.insert("piece".into(), Dynamic::from(s.piece as i64));
            Ok(m)
        },
    );
    engine.register_fn(
        "polyline",
        |c: &mut ScriptCurve, e: Dynamic| -> Fallible<Array> {
            let e = num(&e, "polyline")?;
            super::check_deadline()?;
            // Scripts get at most a million points (arrays of maps are large).
            let limit = 1_000_000;
            match c.0.polyline(e) {
                Ok(line) if line.points.len() <= limit => Ok(points(line.points.into_iter())),
                Ok(line) => fail(format!(
                    "polyline: chord error {e} gives {} points, more than {limit}",
                    line.points.len()
                )),
                Err(err) => fail(format!("polyline: {err}")),
            }
        },
    );
    engine.register_fn(
        "samples",
        |c: &mut ScriptCurve, n: i64| -> Fallible<Array> {
            if !(2..=1_000_000).contains(&n) {
                return fail(format!("samples: expected 2 to 1000000 points, found {n}"));
            }
            let params = uniform_params(c.0.domain(), n as usize);
            Ok(points(params.into_iter().map(|u| c.0.point(u))))
        },
    );
}
