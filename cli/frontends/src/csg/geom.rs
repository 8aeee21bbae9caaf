//! What a statement converts to ([`Geom`]: nothing, a solid or a 2D region) and the state of the
//! conversion ([`Ctx`]: facets, file access, warnings, drawn texts).

use super::Facets;
use super::error::Warning;
use super::flat::Flat;
use super::parser::Stmt;
use super::text::TextCache;
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::MeshResolver;

/// A statement's geometry.
#[derive(Debug, Clone)]
pub(super) enum Geom {
    /// Nothing (an empty group, a zero-size primitive).
    Empty,
    /// A 3D solid.
    Solid(Solid),
    /// A 2D region.
    Flat(Flat),
}

/// The conversion's state: how round primitives are built, where imported files come from and
/// the warnings so far.
pub(super) struct Ctx<'a> {
    pub(super) facets: Facets,
    pub(super) files: &'a dyn MeshResolver,
    pub(super) warnings: Vec<Warning>,
    /// `text()` drawings by their `.scad` source (OpenSCAD runs once per distinct text).
    pub(super) texts: TextCache,
}

impl Ctx<'_> {
    pub(super) fn warn(&mut self, stmt: &Stmt, message: impl Into<String>) {
        self.warnings.push(Warning {
            pos: stmt.pos,
            message: message.into(),
        });
    }
}
