//! The script-side solid ([`Shape`]: a [`Solid`] with its node count) and the conversion of Rhai
//! values (integers or floats, arrays of them) to numbers and vectors.

use glam::DVec3;
use rhai::{Array, Dynamic, EvalAltResult, Position};
use solidkit_kernel::Solid;

/// A failure inside one of our functions; Rhai adds the position of the call.
pub type Fallible<T> = Result<T, Box<EvalAltResult>>;

/// A solid as scripts see it (type name `Solid`): the tree and its node count, a shared subtree
/// counted once per use, kept so the tree-size budget costs nothing to check.
#[derive(Debug, Clone)]
pub struct Shape {
    /// The tree.
    pub solid: Solid,
    /// Nodes of the tree, a shared subtree counted once per use.
    pub nodes: u64,
}

impl Shape {
    /// A leaf.
    pub fn leaf(solid: Solid) -> Shape {
        Shape { solid, nodes: 1 }
    }
}

/// A runtime error with `message`.
pub fn fail<T>(message: impl Into<String>) -> Fallible<T> {
    Err(Box::new(EvalAltResult::ErrorRuntime(
        Dynamic::from(message.into()),
        Position::NONE,
    )))
}

/// A number from an integer or a float; `what` names the argument in errors.
pub fn num(v: &Dynamic, what: &str) -> Fallible<f64> {
    if let Ok(f) = v.as_float() {
        Ok(f)
    } else if let Ok(i) = v.as_int() {
        Ok(i as f64)
    } else {
        fail(format!(
            "{what}: expected a number, found {}",
            v.type_name()
        ))
    }
}

/// A 3-vector from an array of three numbers.
pub fn vec3(v: &Dynamic, what: &str) -> Fallible<DVec3> {
    let Some(items) = v.clone().try_cast::<Array>() else {
        return fail(format!(
            "{what}: expected an array [x, y, z], found {}",
            v.type_name()
        ));
    };
    if items.len() != 3 {
        return fail(format!(
            "{what}: expected 3 numbers [x, y, z], found {}",
            items.len()
        ));
    }
    Ok(DVec3::new(
        num(&items[0], what)?,
        num(&items[1], what)?,
        num(&items[2], what)?,
    ))
}

/// A number or a 3-vector (a number `k` is `[k, k, k]`).
pub fn num_or_vec3(v: &Dynamic, what: &str) -> Fallible<DVec3> {
    if v.is_array() {
        vec3(v, what)
    } else {
        num(v, what).map(DVec3::splat)
    }
}

/// The solids of an array (every element must be a solid).
pub fn shapes(items: Array, what: &str) -> Fallible<Vec<Shape>> {
    items
        .into_iter()
        .enumerate()
        .map(|(i, d)| {
            let name = d.type_name();
            d.try_cast::<Shape>().map_or_else(
                || fail(format!("{what}[{i}]: expected a Solid, found {name}")),
                Ok,
            )
        })
        .collect()
}
