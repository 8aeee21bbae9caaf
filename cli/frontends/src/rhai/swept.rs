//! Swept volumes in scripts: `solid.swept_along(curve)` and `solid.swept_along(curve, #{frame:
//! "rmf" | "fixed", tolerance: T})`, the JSON `swept_volume` node (the union of the solid's
//! copies along the curve, see `solidkit_kernel::swept`); `swept_tolerance(solid)` is the default
//! tolerance for that solid (its bounding-box diagonal / 50).

use super::curve::ScriptCurve;
use super::shape::{Fallible, Shape, fail, num};
use rhai::{Engine, Map};
use solidkit_kernel::swept::{SweptFrame, default_tolerance, swept_volume};

/// The swept volume of `s` along `c` with the options in `m`.
fn build(s: &Shape, c: &ScriptCurve, m: Map, max_nodes: u64) -> Fallible<Shape> {
    super::check_deadline()?;
    let mut frame = SweptFrame::Rmf;
    let mut tolerance = None;
    for (k, v) in m {
        match k.as_str() {
            "frame" => {
                let name = v.to_string();
                frame = SweptFrame::from_name(&name).map_or_else(
                    || {
                        fail(format!(
                            "swept_along: frame: expected \"rmf\" or \"fixed\", found \"{name}\""
                        ))
                    },
                    Ok,
                )?;
            }
            "tolerance" => tolerance = Some(num(&v, "swept_along: tolerance")?),
            other => {
                return fail(format!(
                    "swept_along: unknown option \"{other}\" (expected frame, tolerance)"
                ));
            }
        }
    }
    let swept = match swept_volume(&s.solid, &c.0, frame, tolerance) {
        Ok(swept) => swept,
        Err(e) => return fail(format!("swept_along: {e}")),
    };
    let copies = swept.params.len() as u64;
    let nodes = copies
        .saturating_mul(s.nodes.saturating_add(1))
        .saturating_add(1);
    if nodes > max_nodes {
        return fail(format!(
            "swept_along: the solid would have {nodes} nodes ({copies} copies), more than the \
             limit of {max_nodes}"
        ));
    }
    Ok(Shape {
        solid: swept.solid,
        nodes,
    })
}

/// Registers `swept_along` and `swept_tolerance`.
pub(super) fn register(engine: &mut Engine, max_nodes: u64) {
    engine.register_fn(
        "swept_along",
        move |s: &mut Shape, c: ScriptCurve| -> Fallible<Shape> {
            build(s, &c, Map::new(), max_nodes)
        },
    );
    engine.register_fn(
        "swept_along",
        move |s: &mut Shape, c: ScriptCurve, m: Map| -> Fallible<Shape> {
            build(s, &c, m, max_nodes)
        },
    );
    engine.register_fn("swept_tolerance", |s: &mut Shape| -> f64 {
        default_tolerance(s.solid.bbox().size().length())
    });
}
