//! Writing the quadric family's parameters (the inverse of `read/quadric.rs`).

use super::{num, vec3};
use crate::primitive::Quadric;
use crate::primitive::quadric::QuadricForm;

/// The parameter members of a quadric node, without braces or type.
pub(super) fn members(q: &Quadric) -> String {
    let body = match q.form() {
        QuadricForm::General(c) => {
            let names = ["a", "b", "c", "f", "g", "h", "p", "q", "r", "d"];
            let items: Vec<String> = names
                .iter()
                .zip(c.to_array())
                .map(|(k, v)| format!("\"{k}\": {}", num(v)))
                .collect();
            format!("\"coefficients\": {{{}}}", items.join(", "))
        }
        form => {
            let r: Vec<String> = form.radii().iter().map(|&x| num(x)).collect();
            format!("\"radii\": [{}]", r.join(", "))
        }
    };
    match q.bounds() {
        Some(b) => format!("{body}, \"bounds\": [{}, {}]", vec3(b.min), vec3(b.max)),
        None => body,
    }
}
