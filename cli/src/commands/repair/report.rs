//! What `solidkit repair` prints of a repair: the mode, the change counts, the rebuild.

use crate::args::RepairMode;
use serde_json::{Value, json};
use solidkit_meshing::repair::{Rebuilt, RepairCounts};

/// The mode's name on the command line and in JSON.
pub fn mode_name(m: RepairMode) -> &'static str {
    match m {
        RepairMode::Minimal => "minimal",
        RepairMode::Rebuild => "rebuild",
        RepairMode::Auto => "auto",
    }
}

/// The rebuild's grid and Hausdorff distances as JSON (`relative` to the bbox diagonal).
pub fn rebuild_json(r: &Rebuilt, diagonal: f64) -> Value {
    json!({
        "cells": r.cells,
        "cell": r.cell,
        "hausdorff": r.hausdorff.symmetric,
        "hausdorff_input_to_result": r.hausdorff.a_to_b.max,
        "hausdorff_result_to_input": r.hausdorff.b_to_a.max,
        "relative": r.hausdorff.symmetric / diagonal.max(f64::MIN_POSITIVE),
    })
}

/// The non-zero change counts, one per line.
pub fn changes_text(c: &RepairCounts, weld: f64) -> String {
    let mut s = format!("== minimal repair (weld {weld}):\n");
    let v = serde_json::to_value(c).unwrap_or(Value::Null);
    let mut any = false;
    if let Value::Object(map) = v {
        for (k, x) in map {
            if x.as_f64().is_some_and(|n| n != 0.0) {
                s.push_str(&format!("  {k}: {x}\n"));
                any = true;
            }
        }
    }
    if !any {
        s.push_str("  nothing to change\n");
    }
    s
}
