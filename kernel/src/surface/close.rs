//! Closing a sampled sheet into the boundary of a solid: two layers (offsets along the normal, or
//! the sheet and its projection onto a base plane) joined by walls along the sheet's boundary
//! edges, wound outwards (the whole mesh is flipped when its signed volume comes out negative).

use super::error::SurfaceError;
use super::sample::Sampled;
use super::spec::{Closure, Side};
use crate::IndexedMesh;
use glam::DVec3;
use std::collections::HashSet;

/// The directed edges of `mesh` whose reverse no triangle has: the boundary, in the direction
/// the sheet's triangles run along it.
pub(crate) fn boundary_edges(mesh: &IndexedMesh) -> Vec<(u32, u32)> {
    let edges: HashSet<(u32, u32)> = mesh
        .triangles
        .iter()
        .flat_map(|t| (0..3).map(move |c| (t[c], t[(c + 1) % 3])))
        .collect();
    let mut out: Vec<(u32, u32)> = mesh
        .triangles
        .iter()
        .flat_map(|t| (0..3).map(move |c| (t[c], t[(c + 1) % 3])))
        .filter(|&(a, b)| !edges.contains(&(b, a)))
        .collect();
    out.sort_unstable();
    out
}

/// Signed volume enclosed by a triangle mesh (positive when wound outwards).
pub(crate) fn signed_volume(mesh: &IndexedMesh) -> f64 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            a.dot(b.cross(c))
        })
        .sum::<f64>()
        / 6.0
}

/// The closed, outward-wound boundary of the solid `closure` makes of `sheet`.
pub fn close(sheet: &Sampled, closure: Closure) -> Result<IndexedMesh, SurfaceError> {
    let mesh = &sheet.mesh;
    let boundary = boundary_edges(mesh);
    let (outer, inner): (Vec<DVec3>, Vec<DVec3>) = match closure {
        Closure::Closed => {
            if !boundary.is_empty() {
                return Err(SurfaceError::invalid(
                    "thickness",
                    format!(
                        "the surface is open ({} boundary edges): give \"thickness\" or \"base\"",
                        boundary.len()
                    ),
                ));
            }
            return Ok(outward(mesh.clone()));
        }
        Closure::Thickness { thickness, side } => {
            if !(thickness.is_finite() && thickness > 0.0) {
                return Err(SurfaceError::invalid(
                    "thickness",
                    "expected a positive number",
                ));
            }
            let (a, b) = match side {
                Side::Both => (0.5 * thickness, -0.5 * thickness),
                Side::Front => (thickness, 0.0),
                Side::Back => (0.0, -thickness),
            };
            let layer = |d: f64| {
                mesh.positions
                    .iter()
                    .zip(&sheet.normals)
                    .map(|(p, n)| *p + *n * d)
                    .collect()
            };
            (layer(a), layer(b))
        }
        Closure::Base { z } => {
            if !z.is_finite() {
                return Err(SurfaceError::invalid("base", "expected a finite number"));
            }
            if mesh.positions.iter().any(|p| p.z <= z) {
                return Err(SurfaceError::invalid(
                    "base",
                    "the base plane must lie below every point of the surface",
                ));
            }
            check_graph(mesh)?;
            let base = mesh
                .positions
                .iter()
                .map(|p| p.truncate().extend(z))
                .collect();
            (mesh.positions.clone(), base)
        }
    };
    let n = mesh.positions.len() as u32;
    let mut positions = outer;
    positions.extend(inner);
    let mut triangles = Vec::with_capacity(2 * mesh.triangles.len() + 2 * boundary.len());
    triangles.extend(mesh.triangles.iter().copied());
    triangles.extend(
        mesh.triangles
            .iter()
            .map(|t| [t[0] + n, t[2] + n, t[1] + n]),
    );
    for &(a, b) in &boundary {
        triangles.push([a, a + n, b]);
        triangles.push([b, a + n, b + n]);
    }
    Ok(outward(IndexedMesh::new(positions, triangles)))
}

/// The mesh wound outwards: flipped when its signed volume is negative.
fn outward(mut mesh: IndexedMesh) -> IndexedMesh {
    if signed_volume(&mesh) < 0.0 {
        for t in &mut mesh.triangles {
            t.swap(1, 2);
        }
    }
    mesh
}

/// Fails unless the sheet projects one-to-one onto the `xy` plane as far as its triangles tell:
/// every non-degenerate projected triangle turns the same way.
fn check_graph(mesh: &IndexedMesh) -> Result<(), SurfaceError> {
    let (mut pos, mut neg) = (0usize, 0usize);
    let scale = mesh
        .positions
        .iter()
        .fold(0.0f64, |m, p| m.max(p.truncate().abs().max_element()));
    let eps = 1e-12 * scale * scale;
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize].truncate());
        let area = (b - a).perp_dot(c - a);
        if area > eps {
            pos += 1;
        } else if area < -eps {
            neg += 1;
        }
    }
    if pos > 0 && neg > 0 {
        return Err(SurfaceError::invalid(
            "base",
            "the surface folds over the base plane (it is not a graph z = f(x, y)): use \
             \"thickness\" instead",
        ));
    }
    Ok(())
}
