//! Discrete curvatures of a triangle mesh, per vertex (Meyer, Desbrun, Schröder, Barr, "Discrete
//! differential-geometry operators for triangulated 2-manifolds", 2003):
//!
//! - **Gaussian** `K_i = (2π − Σ θ_j) / A_i`: the angle defect over the mixed area `A_i` (the
//!   Voronoi area of the vertex within non-obtuse triangles, half or a quarter of an obtuse
//!   triangle's area otherwise; the mixed areas tile the surface). On a boundary vertex the defect
//!   is `π − Σ θ_j` (the geodesic curvature of the boundary), so that Gauss–Bonnet holds for every
//!   mesh: `Σ_i K_i A_i = 2π χ` with `χ = V − E + F` (an identity of the angles, exact to
//!   rounding, which [`MeshCurvature::gauss_bonnet_error`] reports).
//! - **Mean** `H_i = ½ n_i · (1 / (2A_i)) Σ_j (cot α_ij + cot β_ij)(x_i − x_j)`: half the
//!   cotangent Laplacian of the position along the angle-weighted vertex normal `n_i`. With
//!   triangles wound counter-clockwise seen from outside, `H > 0` where the surface is convex: a
//!   sphere of radius `r` has `K = 1/r²`, `H = 1/r`. On boundary vertices the Laplacian misses
//!   the outer half of its ring: `H` is written but not meaningful there (the `boundary` flag).
//! - **Principal** `k₁,₂ = H ± √max(H² − K, 0)`.
//!
//! Vertices no triangle uses, and vertices whose mixed area is zero (only degenerate triangles),
//! get zero curvatures and count in [`MeshCurvature::skipped`].

#[cfg(test)]
mod tests;

use glam::DVec3;
use solidkit_kernel::IndexedMesh;
use std::collections::HashMap;
use std::f64::consts::PI;

/// The curvatures of one vertex.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VertexCurvature {
    /// Gaussian curvature `K`.
    pub gaussian: f64,
    /// Mean curvature `H` (positive where convex, for outward-wound triangles).
    pub mean: f64,
    /// The larger principal curvature.
    pub k1: f64,
    /// The smaller principal curvature.
    pub k2: f64,
    /// Whether the vertex is on the boundary (an edge used by one triangle).
    pub boundary: bool,
    /// The mixed area `A_i`.
    pub area: f64,
}

/// Per-vertex curvatures of a mesh and the Gauss–Bonnet check.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshCurvature {
    /// One entry per vertex of the mesh.
    pub vertices: Vec<VertexCurvature>,
    /// `Σ` of the angle defects (`2π − Σθ`, `π − Σθ` on the boundary) over used vertices.
    pub total_angle_defect: f64,
    /// `χ = V − E + F` over the used vertices, the distinct edges and the triangles.
    pub euler_characteristic: i64,
    /// Vertices without curvature (unused, or no area).
    pub skipped: usize,
    /// Vertices on the boundary.
    pub boundary_vertices: usize,
}

impl MeshCurvature {
    /// `|Σ angle defect − 2πχ|`: zero up to rounding for every mesh (Gauss–Bonnet).
    pub fn gauss_bonnet_error(&self) -> f64 {
        (self.total_angle_defect - 2.0 * PI * self.euler_characteristic as f64).abs()
    }
}

/// The angle at `a` of the triangle `a, b, c` (robust for thin triangles).
fn angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (u, v) = (b - a, c - a);
    u.cross(v).length().atan2(u.dot(v))
}

/// `cot` of the angle at `a`, 0 for a degenerate triangle.
fn cot(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (u, v) = (b - a, c - a);
    let s = u.cross(v).length();
    if s > 0.0 { u.dot(v) / s } else { 0.0 }
}

/// The discrete curvatures of `mesh` (see the [module docs](self)). Triangles with an index out
/// of range or a repeated corner are ignored.
pub fn mesh_curvature(mesh: &IndexedMesh) -> MeshCurvature {
    let n = mesh.positions.len();
    let p = &mesh.positions;
    let mut angle_sum = vec![0.0; n];
    let mut area = vec![0.0; n];
    let mut laplace = vec![DVec3::ZERO; n];
    let mut normal = vec![DVec3::ZERO; n];
    let mut used = vec![false; n];
    let mut edges: HashMap<(u32, u32), u32> = HashMap::with_capacity(mesh.triangles.len() * 3 / 2);
    let mut faces = 0i64;
    for t in &mesh.triangles {
        if t.iter().any(|&i| i as usize >= n) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            continue;
        }
        faces += 1;
        let x = t.map(|i| p[i as usize]);
        let face = (x[1] - x[0]).cross(x[2] - x[0]);
        let tri_area = 0.5 * face.length();
        let face_n = face.normalize_or_zero();
        let angles = [0, 1, 2].map(|c| angle(x[c], x[(c + 1) % 3], x[(c + 2) % 3]));
        let obtuse = angles.iter().position(|&a| a > 0.5 * PI);
        for c in 0..3 {
            let i = t[c] as usize;
            let (j, k) = ((c + 1) % 3, (c + 2) % 3);
            used[i] = true;
            angle_sum[i] += angles[c];
            normal[i] += face_n * angles[c];
            area[i] += match obtuse {
                None => {
                    // Voronoi: (|x_i − x_j|² cot θ_k + |x_i − x_k|² cot θ_j) / 8.
                    ((x[c] - x[j]).length_squared() * cot(x[k], x[c], x[j])
                        + (x[c] - x[k]).length_squared() * cot(x[j], x[k], x[c]))
                        / 8.0
                }
                Some(o) if o == c => tri_area / 2.0,
                Some(_) => tri_area / 4.0,
            };
            // The edge (i, j) faces the angle at k.
            let w = cot(x[k], x[c], x[j]);
            let (a, b) = (t[c], t[j]);
            laplace[a as usize] += w * (x[c] - x[j]);
            laplace[b as usize] += w * (x[j] - x[c]);
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let mut boundary = vec![false; n];
    for (&(a, b), &count) in &edges {
        if count == 1 {
            boundary[a as usize] = true;
            boundary[b as usize] = true;
        }
    }
    let mut total = 0.0;
    let mut skipped = 0;
    let mut vertices = vec![VertexCurvature::default(); n];
    for i in 0..n {
        if !used[i] {
            skipped += 1;
            continue;
        }
        let full = if boundary[i] { PI } else { 2.0 * PI };
        let defect = full - angle_sum[i];
        total += defect;
        let a = area[i];
        let nrm = normal[i].normalize_or_zero();
        if a.is_nan() || a <= 0.0 {
            skipped += 1;
            vertices[i].boundary = boundary[i];
            continue;
        }
        let gaussian = defect / a;
        let mean = 0.5 * (laplace[i] / (2.0 * a)).dot(nrm);
        let r = (mean * mean - gaussian).max(0.0).sqrt();
        vertices[i] = VertexCurvature {
            gaussian,
            mean,
            k1: mean + r,
            k2: mean - r,
            boundary: boundary[i],
            area: a,
        };
    }
    let v_used = used.iter().filter(|&&u| u).count() as i64;
    MeshCurvature {
        vertices,
        total_angle_defect: total,
        euler_characteristic: v_used - edges.len() as i64 + faces,
        skipped,
        boundary_vertices: boundary.iter().filter(|&&b| b).count(),
    }
}
