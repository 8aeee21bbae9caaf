//! The library-level integration suites, one module per file, in one test binary: the whole path
//! from tree to verified mesh (acceptance, models, families of solids, dual contouring, coincident
//! faces, edge contact, subdivision). One binary instead of one per file: each release test binary
//! links the whole kernel and mesher, and after a change to the shared helpers the fifteen
//! binaries took 82 s to rebuild here, the one binary 10 s.
//!
//! Run one suite with a filter: `cargo test --release -p solidkit-tests --test integration models::`.

#[path = "acceptance.rs"]
mod acceptance;
#[path = "coincident.rs"]
mod coincident;
#[path = "dual_contouring.rs"]
mod dual_contouring;
#[path = "edge_contact.rs"]
mod edge_contact;
#[path = "families_blends.rs"]
mod families_blends;
#[path = "families_blobs.rs"]
mod families_blobs;
#[path = "families_formulas.rs"]
mod families_formulas;
#[path = "families_heightfields.rs"]
mod families_heightfields;
#[path = "families_polyhedra.rs"]
mod families_polyhedra;
#[path = "families_quadrics.rs"]
mod families_quadrics;
#[path = "families_surfaces.rs"]
mod families_surfaces;
#[path = "families_sweeps.rs"]
mod families_sweeps;
#[path = "families_swept.rs"]
mod families_swept;
#[path = "models.rs"]
mod models;
#[path = "subdivision.rs"]
mod subdivision;
