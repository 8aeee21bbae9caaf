//! The Laplacian `Δh = h_xx + h_yy` of a graph surface `z = h(x, y)`, exact from second
//! derivatives: for a `heightfield` node from `h`'s own derivatives, for a rectangle-parametrised
//! surface node `p(s, t) = (x, y, z)` whose projection onto the `xy` plane is regular, by the chain
//! rule. With `a = (x_s, y_s)`, `b = (x_t, y_t)`, `M = [a b]` and the gradient `g = ∇h` solving
//! `Mᵀ g = (z_s, z_t)`, the Hessian of `h` satisfies `Mᵀ H M = R` with
//! `R = [[z_ss − g·(x_ss, y_ss), z_st − g·(x_st, y_st)], [·, z_tt − g·(x_tt, y_tt)]]`, so
//! `Δh = tr H = tr(R (MᵀM)⁻¹) = (R_ss b·b − 2 R_st a·b + R_tt a·a) / (det M)²`.

use solidkit_kernel::IndexedMesh;
use solidkit_kernel::patch::monge_curvature;
use solidkit_kernel::primitive::HeightField;
use solidkit_kernel::surface::SurfaceDerivatives;
use solidkit_kernel::tessellate;
use solidkit_meshing::curvature::VertexCurvature;

/// Segments per direction of a height field's grid.
const HEIGHT_SEGMENTS: usize = 128;

/// `Δh` at a surface point seen as a graph over `xy`; `None` where the projection onto the plane
/// is singular (`|det M|` below 10⁻⁹ of `|a| |b|`).
pub fn graph_laplacian(d: &SurfaceDerivatives) -> Option<f64> {
    let (a, b) = (d.pu.truncate(), d.pv.truncate());
    let det = a.perp_dot(b);
    if !det.is_finite() || det.abs() <= 1e-9 * a.length() * b.length() {
        return None;
    }
    // Mᵀ g = (z_s, z_t): rows a and b.
    let (zs, zt) = (d.pu.z, d.pv.z);
    let g = glam::DVec2::new(zs * b.y - zt * a.y, a.x * zt - b.x * zs) / det;
    let r = |q: glam::DVec3| q.z - g.dot(q.truncate());
    let (rss, rst, rtt) = (r(d.puu), r(d.puv), r(d.pvv));
    let lap = (rss * b.dot(b) - 2.0 * rst * a.dot(b) + rtt * a.dot(a)) / (det * det);
    lap.is_finite().then_some(lap)
}

/// The top surface of a height field on a regular grid, with the exact curvatures of `h`
/// (Monge patch formulas, mean curvature turned to the mesh convention) and `Δh` per vertex.
pub fn height_field(
    hf: &HeightField,
) -> anyhow::Result<(IndexedMesh, Vec<VertexCurvature>, Vec<f64>)> {
    let n = HEIGHT_SEGMENTS;
    let mesh = tessellate::regular_grid(n + 1, n + 1, |u, v| hf.point_at(u, v))?;
    let mut values = Vec::with_capacity(mesh.positions.len());
    let mut laplacian = Vec::with_capacity(mesh.positions.len());
    for p in &mesh.positions {
        let d = hf.derivatives(p.x, p.y);
        let c = monge_curvature(&d);
        values.push(super::vertex_curvature(c.gaussian, c.mean));
        laplacian.push(d.hxx + d.hyy);
    }
    Ok((mesh, values, laplacian))
}
