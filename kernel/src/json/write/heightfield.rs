//! Writing `heightfield` parameters (the inverse of `read/heightfield.rs`). A height field read
//! from a PNG is written with its file path again, not its samples.

use super::{num, string};
use crate::primitive::HeightField;
use crate::primitive::heightfield::{HeightGrid, HeightSource};

fn rows(g: &HeightGrid) -> String {
    let rows: Vec<String> = g
        .rows()
        .map(|r| {
            format!(
                "[{}]",
                r.iter().map(|&x| num(x)).collect::<Vec<_>>().join(", ")
            )
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

/// The parameter members of a height-field node, without braces or type.
pub(super) fn members(h: &HeightField) -> String {
    let head = format!(
        "\"min\": [{}, {}], \"max\": [{}, {}], \"base\": {}",
        num(h.min().x),
        num(h.min().y),
        num(h.max().x),
        num(h.max().y),
        num(h.base())
    );
    let body = match (h.png_origin(), h.source()) {
        (Some(o), HeightSource::Samples { interpolation, .. }) => format!(
            "\"png\": {}, \"heights\": [{}, {}], \"interpolation\": \"{}\"",
            string(&o.path),
            num(o.heights[0]),
            num(o.heights[1]),
            interpolation.name()
        ),
        (_, HeightSource::Bezier(g)) => format!("\"bezier\": {}", rows(g)),
        (
            _,
            HeightSource::Samples {
                grid,
                interpolation,
            },
        ) => format!(
            "\"samples\": {}, \"interpolation\": \"{}\"",
            rows(grid),
            interpolation.name()
        ),
    };
    format!("{head}, {body}")
}
