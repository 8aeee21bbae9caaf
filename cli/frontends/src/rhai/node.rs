//! `node(map)`: any node of the JSON tree format from a Rhai map of its keys (solids allowed as
//! values, e.g. `child` or `children`), built by the kernel's JSON reader so every family is
//! reachable and checked the same way as in `.json` files.

use super::shape::{Fallible, Shape, fail};
use rhai::{Dynamic, Map};
use serde_json::Value;
use solidkit_kernel::json::{self, MeshResolver};

/// Deepest nesting of arrays and maps accepted in a node description.
const MAX_DEPTH: usize = 64;

/// The solid described by `m`, within the budget of `max_nodes` nodes.
pub(super) fn from_map(m: Map, resolver: &dyn MeshResolver, max_nodes: u64) -> Fallible<Shape> {
    let mut nodes = 1u64;
    let mut text = String::new();
    write(&mut text, Dynamic::from_map(m), &mut nodes, 0)?;
    if nodes > max_nodes {
        return fail(format!(
            "the solid would have {nodes} nodes, more than the limit of {max_nodes}"
        ));
    }
    match json::from_str_with(&text, resolver) {
        Ok(solid) => Ok(Shape { solid, nodes }),
        Err(solidkit_kernel::KernelError::Json { message, .. }) => fail(format!("node: {message}")),
        Err(e) => fail(format!("node: {e}")),
    }
}

/// The JSON text of a map of plain values (numbers, strings, booleans, arrays, maps), for readers
/// of objects that are not nodes (curves); `what` names the function in errors.
pub(super) fn json_text(m: Map, what: &str) -> Fallible<String> {
    let mut nodes = 0u64;
    let mut text = String::new();
    write(&mut text, Dynamic::from_map(m), &mut nodes, 0)
        .map_err(|e| format!("{what}: {}", e.to_string().trim_start_matches("node: ")))?;
    if nodes > 0 {
        return fail(format!("{what}: a Solid cannot be part of a curve"));
    }
    Ok(text)
}

/// Appends the JSON text of `v` to `out` (text, not a `serde_json::Value`, so the embedded
/// trees of solids may be of any depth: the kernel's reader handles them with a work list).
fn write(out: &mut String, v: Dynamic, nodes: &mut u64, depth: usize) -> Fallible<()> {
    if depth > MAX_DEPTH {
        return fail(format!("node: values nested deeper than {MAX_DEPTH}"));
    }
    if v.is_unit() {
        out.push_str("null");
    } else if let Ok(b) = v.as_bool() {
        out.push_str(if b { "true" } else { "false" });
    } else if let Ok(i) = v.as_int() {
        out.push_str(&i.to_string());
    } else if let Ok(f) = v.as_float() {
        if !f.is_finite() {
            return fail(format!("node: {f} is not a finite number"));
        }
        out.push_str(&format!("{f:?}"));
    } else if v.is_string() {
        out.push_str(&Value::String(v.to_string()).to_string());
    } else if v.is_array() {
        out.push('[');
        for (i, d) in v.cast::<rhai::Array>().into_iter().enumerate() {
            if i > 0 {
                out.push_str(", ");
            }
            write(out, d, nodes, depth + 1)?;
        }
        out.push(']');
    } else if v.is_map() {
        out.push('{');
        for (i, (k, d)) in v.cast::<Map>().into_iter().enumerate() {
            if i > 0 {
                out.push_str(", ");
            }
            out.push_str(&Value::String(k.to_string()).to_string());
            out.push_str(": ");
            write(out, d, nodes, depth + 1)?;
        }
        out.push('}');
    } else {
        let name = v.type_name();
        let Some(shape) = v.try_cast::<Shape>() else {
            return fail(format!("node: a {name} cannot be part of a node"));
        };
        *nodes = nodes.saturating_add(shape.nodes);
        let doc = json::to_string(&shape.solid);
        // The envelope is `{ "format": …, "version": …, "root": NODE }`: keep NODE.
        let body = doc
            .split_once("\"root\": ")
            .and_then(|(_, rest)| rest.trim_end().strip_suffix('}'))
            .ok_or_else(|| "node: cannot embed a solid".to_string())?;
        out.push_str(body);
    }
    Ok(())
}
