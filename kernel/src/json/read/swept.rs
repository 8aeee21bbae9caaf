//! Reading the `swept_volume` node: `{"type": "swept_volume", "child": NODE, "path": CURVE,
//! "frame": "rmf" | "fixed", "tolerance": T}` (frame default `rmf`, tolerance default the
//! child box's diagonal / 50). The child is built first; the node becomes the union of its
//! copies along the path ([`crate::swept`]), which is what the writer writes back.

use super::super::document::Value;
use super::R;
use crate::solid::Solid;
use crate::swept::{SweptFrame, swept_volume};

impl super::Params<'_, '_> {
    /// The swept volume of the node's one built child.
    pub(super) fn swept_volume(&self, children: Vec<Solid>) -> R<Solid> {
        self.reject_unknown(&["child", "path", "frame", "tolerance"])?;
        let child_at = self.at("child")?;
        let child = children
            .first()
            .ok_or_else(|| self.fail(child_at, "child", "missing child"))?;
        let nested = self.sweep_nested("path")?;
        let path = self.curve_object(&nested)?;
        let frame = match super::find(self.entries, "frame") {
            None => SweptFrame::Rmf,
            Some(i) => match &self.reader.doc.values[i as usize] {
                Value::String(s) => SweptFrame::from_name(s).ok_or_else(|| {
                    self.fail(
                        i,
                        "frame",
                        format!("expected \"rmf\" or \"fixed\", found \"{s}\""),
                    )
                })?,
                v => {
                    return Err(self.fail(
                        i,
                        "frame",
                        format!("expected \"rmf\" or \"fixed\", found {}", v.type_name()),
                    ));
                }
            },
        };
        let tolerance = match super::find(self.entries, "tolerance") {
            Some(i) => Some(self.number_at(i, "tolerance")?),
            None => None,
        };
        match swept_volume(child, &path, frame, tolerance) {
            Ok(s) => Ok(s.solid),
            Err(e) => {
                let key = e.parameter();
                let at = super::find(self.entries, key).unwrap_or(self.index);
                let message = e.to_string();
                // Messages about a key start with it; the others get the key in front.
                let message = message
                    .strip_prefix(&format!("{key}: "))
                    .map_or(message.clone(), str::to_string);
                Err(self.fail(at, key, message))
            }
        }
    }
}
