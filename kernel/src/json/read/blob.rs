//! Reading `blob` nodes: `{"type": "blob", "threshold": T, "balls": [{"center": [x, y, z],
//! "strength": b, "sharpness": a}, …]}` for the solid `Σ b exp(−a r²) ≥ T`.

use super::super::document::Value;
use super::{Params, R, find};
use crate::primitive::Primitive;
use crate::primitive::blob::{Ball, Blob};
use glam::DVec3;
use std::sync::Arc;

const BALL_KEYS: [&str; 3] = ["center", "strength", "sharpness"];

impl Params<'_, '_> {
    /// The primitive of a `blob` node.
    pub(super) fn blob(&self) -> R<(Primitive, &'static [&'static str])> {
        let threshold = self.number("threshold")?;
        let list = self.at("balls")?;
        let Value::Array(items) = &self.reader.doc.values[list as usize] else {
            return Err(self.fail(list, "balls", "expected an array of balls"));
        };
        let mut balls = Vec::with_capacity(items.len());
        for (k, &item) in items.iter().enumerate() {
            let key = format!("balls[{k}]");
            let Value::Object(entries) = &self.reader.doc.values[item as usize] else {
                return Err(self.fail(item, &key, "expected a ball object"));
            };
            for (name, v) in entries {
                if !BALL_KEYS.contains(&name.as_str()) {
                    let message = format!(
                        "unknown key \"{name}\" (expected one of: {})",
                        BALL_KEYS.join(", ")
                    );
                    return Err(self.fail(*v, &format!("{key}.{name}"), message));
                }
            }
            let get = |name: &str| {
                find(entries, name)
                    .ok_or_else(|| self.fail(item, &key, format!("missing key \"{name}\"")))
            };
            let center_key = format!("{key}.center");
            let ball = Ball {
                center: DVec3::from_array(self.numbers::<3>(get("center")?, &center_key)?),
                strength: self.number_at(get("strength")?, &format!("{key}.strength"))?,
                sharpness: self.number_at(get("sharpness")?, &format!("{key}.sharpness"))?,
            };
            ball.validate().map_err(|e| {
                let at = find(entries, e.parameter).unwrap_or(item);
                self.fail(at, &format!("{key}.{}", e.parameter), e.problem)
            })?;
            balls.push(ball);
        }
        let blob = Blob::new(balls, threshold).map_err(|e| {
            let at = self.at(e.parameter).unwrap_or(self.index);
            self.fail(at, e.parameter, e.problem)
        })?;
        Ok((Primitive::Blob(Arc::new(blob)), &["threshold", "balls"]))
    }
}
