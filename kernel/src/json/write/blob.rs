//! Writing `blob` parameters (the inverse of `read/blob.rs`).

use super::{num, vec3};
use crate::primitive::Blob;

/// The parameter members of a blob node, without braces or type.
pub(super) fn members(b: &Blob) -> String {
    let balls: Vec<String> = b
        .balls()
        .iter()
        .map(|ball| {
            format!(
                "{{\"center\": {}, \"strength\": {}, \"sharpness\": {}}}",
                vec3(ball.center),
                num(ball.strength),
                num(ball.sharpness)
            )
        })
        .collect();
    format!(
        "\"threshold\": {}, \"balls\": [{}]",
        num(b.threshold()),
        balls.join(", ")
    )
}
