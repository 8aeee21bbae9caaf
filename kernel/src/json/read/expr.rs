//! Reading the `expr` node: a formula and the box that cuts it.

use super::super::document::Value;
use super::{Params, R};
use crate::primitive::{Expr, Primitive, expr::ExprError};
use std::sync::Arc;

impl Params<'_, '_> {
    /// `{"type": "expr", "formula": "...", "bounds": [[x, y, z], [x, y, z]]}`.
    pub(super) fn expr(&self) -> R<(Primitive, &'static [&'static str])> {
        let i = self.at("formula")?;
        let Value::String(formula) = &self.reader.doc.values[i as usize] else {
            return Err(self.fail(i, "formula", "expected a string such as \"x*x + y*y - z\""));
        };
        let b = self.at("bounds")?;
        let bounds = self
            .quadric_bounds("bounds")?
            .ok_or_else(|| self.fail(b, "bounds", "expected [[min x, y, z], [max x, y, z]]"))?;
        let e = Expr::new(formula, bounds).map_err(|e| match e {
            ExprError::Parse(p) => self.fail(i, "formula", p),
            ExprError::Bounds(b) => {
                let at = self.at("bounds").unwrap_or(self.index);
                self.fail(at, "bounds", b.problem)
            }
        })?;
        Ok((Primitive::Expr(Arc::new(e)), &["formula", "bounds"]))
    }
}
