//! The self-checks of a generated suite: stated topology and volume tolerance met, no
//! self-intersections outside the `broken` suite, broken meshes reporting exactly the defects
//! put in. `solidkit gen` exits 1 and the Python package's `gen` raises when any fails.

use super::Manifest;

impl Manifest {
    /// Every contradiction between a solid's measured values and what the manifest states, one
    /// line each (empty when the suite checks out).
    pub fn failures(&self) -> Vec<String> {
        failures(self)
    }
}

/// See [`Manifest::failures`].
fn failures(m: &Manifest) -> Vec<String> {
    let mut out = Vec::new();
    for r in &m.solids {
        if r.error.topology_matches == Some(false) {
            out.push(format!(
                "{}: topology (shells {}, genus {:?}, chi {}) differs from the truth (shells {:?}, genus {:?}, chi {:?})",
                r.name,
                r.mesh.shells,
                r.mesh.genus,
                r.mesh.euler_characteristic,
                r.truth.shells,
                r.truth.genus,
                r.truth.euler_characteristic
            ));
        }
        if r.error.volume_within_tolerance == Some(false) {
            out.push(format!(
                "{}: volume error {:?} exceeds the stated tolerance {:?}",
                r.name, r.error.volume, r.error.volume_tolerance
            ));
        }
        if r.defects.is_none() && r.mesh.self_intersections.unwrap_or(0) > 0 {
            out.push(format!(
                "{}: {} self-intersecting triangle pairs",
                r.name,
                r.mesh.self_intersections.unwrap_or(0)
            ));
        }
        if let Some(d) = &r.defects {
            let e = &d.expected;
            let got = (
                r.mesh.boundary_edges,
                r.mesh.non_manifold_edges,
                r.mesh.non_manifold_vertices,
                r.mesh.inconsistent_edges,
                r.mesh.degenerate_faces,
                r.mesh.vertices,
                r.mesh.edges,
                r.mesh.faces,
                r.mesh.self_intersections.unwrap_or(e.self_intersections),
            );
            let want = (
                e.boundary_edges,
                e.non_manifold_edges,
                e.non_manifold_vertices,
                e.inconsistent_edges,
                e.degenerate_faces,
                e.vertices,
                e.edges,
                e.faces,
                e.self_intersections,
            );
            if got != want {
                out.push(format!(
                    "{}: report (boundary, non-manifold edges, non-manifold vertices, inconsistent, degenerate, V, E, F, self-intersections) = {got:?}, expected {want:?}",
                    r.name
                ));
            }
        }
    }
    out
}
