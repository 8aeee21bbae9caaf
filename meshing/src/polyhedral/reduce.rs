//! Booleans of many operands as balanced trees: `n` operands take `⌈log₂ n⌉` rounds of pairwise
//! Booleans (a left fold would take `n` rounds over an ever larger result), the pairs of each
//! round in parallel. A Boolean that fails inside the kernel (a panic of the port) is an error
//! here, never a crash.

use super::{Polyhedral, PolyhedralError};
use manifold_rust::manifold::Manifold;
use manifold_rust::types::Error as Status;
use rayon::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind};

type Op = fn(&Manifold, &Manifold) -> Manifold;

/// One Boolean, its failures as errors.
fn apply(op: Op, a: &Polyhedral, b: &Polyhedral) -> Result<Polyhedral, PolyhedralError> {
    let m = catch_unwind(AssertUnwindSafe(|| op(&a.0, &b.0)))
        .map_err(|_| PolyhedralError::Failed("the Boolean kernel stopped".into()))?;
    match m.status() {
        Status::NoError => Ok(Polyhedral(m)),
        other => Err(PolyhedralError::Failed(format!("{other:?}"))),
    }
}

/// Operands combined pairwise, round by round, by `op`; `None` for none.
fn reduce(mut parts: Vec<Polyhedral>, op: Op) -> Result<Option<Polyhedral>, PolyhedralError> {
    while parts.len() > 1 {
        parts = parts
            .par_chunks(2)
            .map(|pair| match pair {
                [a, b] => apply(op, a, b),
                [a] => Ok(a.clone()),
                _ => unreachable!("chunks of one or two"),
            })
            .collect::<Result<_, _>>()?;
    }
    Ok(parts.pop())
}

/// The union of the operands (empty for none).
pub fn union_all(parts: Vec<Polyhedral>) -> Result<Polyhedral, PolyhedralError> {
    let parts: Vec<Polyhedral> = parts.into_iter().filter(|p| !p.is_empty()).collect();
    Ok(reduce(parts, Manifold::union)?.unwrap_or_else(Polyhedral::empty))
}

/// The intersection of the operands (empty for none, or when one is empty).
pub fn intersection_all(parts: Vec<Polyhedral>) -> Result<Polyhedral, PolyhedralError> {
    if parts.iter().any(Polyhedral::is_empty) {
        return Ok(Polyhedral::empty());
    }
    Ok(reduce(parts, Manifold::intersection)?.unwrap_or_else(Polyhedral::empty))
}

/// `base` minus the union of `others`.
pub fn difference(
    base: Polyhedral,
    others: Vec<Polyhedral>,
) -> Result<Polyhedral, PolyhedralError> {
    if base.is_empty() {
        return Ok(base);
    }
    let cut = union_all(others)?;
    if cut.is_empty() {
        return Ok(base);
    }
    apply(Manifold::difference, &base, &cut)
}
