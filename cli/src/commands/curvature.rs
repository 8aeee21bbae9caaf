//! `solidkit curvature`: per-vertex Gaussian, mean and principal curvatures written as PLY
//! vertex properties, with a summary (min, max, area-weighted mean) and the Gauss–Bonnet check.
//!
//! A mesh file gets the discrete curvatures of `solidkit_meshing::curvature`. A tree whose root
//! is a rectangle-parametrised surface node (`bezier_patch`, `interpolating_patch`,
//! `bspline_surface`, `nurbs_surface`, `param_surface`) gets the exact curvatures from its fundamental forms at the vertices of its
//! regular tessellation (the open sheet, before any thickness or base), with the mean curvature's
//! sign turned to the mesh convention (positive where the surface bends away from its normal,
//! `p_u × p_v`), and the discrete ones of the same grid beside them in the summary. A
//! `heightfield` root gets the exact Monge-patch curvatures of `h` on a 129 × 129 grid of its top
//! surface. Where the sheet is a graph `z = h(x, y)` (every height field; a surface node whose
//! projection onto `xy` is regular with one orientation, such as `param_surface` with only `z`),
//! the Laplacian `Δh = h_xx + h_yy` is written too (PLY property `laplacian`, summary key
//! `laplacian`), exact from second derivatives (see `laplacian.rs`).

use crate::args::CurvatureArgs;
use crate::input::load_solid;
use crate::output::{out, outln};
use anyhow::{Result, anyhow, bail};
use serde_json::{Value, json};
use solidkit_kernel::primitive::{MeshSource, NoMeshResolver, Primitive};
use solidkit_kernel::surface::SurfaceSpec;
use solidkit_kernel::{IndexedMesh, NodeKind, tessellate};
use solidkit_meshing::curvature::{MeshCurvature, VertexCurvature, mesh_curvature};
use solidkit_meshing::io::{MeshFormat, read_mesh, write_ply_with_scalars};

mod laplacian;

/// Computes, writes the PLY and prints the summary; exit code 0.
pub fn run(a: &CurvatureArgs) -> Result<u8> {
    let name = a.input.display().to_string();
    let is_mesh = MeshFormat::from_path(&a.input).is_ok();
    let (mesh, values, method, discrete, laplacian) = if is_mesh {
        let mesh = read_mesh(&a.input)?;
        let c = mesh_curvature(&mesh);
        let values = c.vertices.clone();
        (mesh, values, "discrete", c, None)
    } else {
        let solid = load_solid(&a.input, &a.allow_path, &[])?;
        let not_surface = || {
            anyhow!(
                "{name}: the root is not a parametric surface or height field node; mesh it first"
            )
        };
        let (mesh, mut values, laplacian) = match solid.kind() {
            NodeKind::Primitive(Primitive::Mesh(m)) => match m.source() {
                MeshSource::Surface(s) => parametric(s).map_err(|e| anyhow!("{name}: {e}"))?,
                _ => return Err(not_surface()),
            },
            NodeKind::Primitive(Primitive::HeightField(hf)) => {
                let (m, v, l) = laplacian::height_field(hf).map_err(|e| anyhow!("{name}: {e}"))?;
                (m, v, Some(l))
            }
            _ => return Err(not_surface()),
        };
        let c = mesh_curvature(&mesh);
        for (v, d) in values.iter_mut().zip(&c.vertices) {
            v.boundary = d.boundary;
        }
        (mesh, values, "parametric", c, laplacian)
    };
    let column = |f: fn(&VertexCurvature) -> f64| values.iter().map(f).collect::<Vec<f64>>();
    let (k, h, k1, k2) = (
        column(|v| v.gaussian),
        column(|v| v.mean),
        column(|v| v.k1),
        column(|v| v.k2),
    );
    let boundary = column(|v| if v.boundary { 1.0 } else { 0.0 });
    let mut scalars: Vec<(&str, &[f64])> = vec![
        ("gaussian", &k),
        ("mean", &h),
        ("k1", &k1),
        ("k2", &k2),
        ("boundary", &boundary),
    ];
    if let Some(l) = &laplacian {
        scalars.push(("laplacian", l));
    }
    write_ply_with_scalars(&a.output, &mesh, &scalars)?;
    let mut summary = summary(method, &mesh, &values, &discrete);
    summary["laplacian"] = match &laplacian {
        Some(l) => {
            let areas: Vec<f64> = discrete.vertices.iter().map(|v| v.area).collect();
            let with: Vec<VertexCurvature> = values
                .iter()
                .zip(l)
                .map(|(v, &x)| VertexCurvature { mean: x, ..*v })
                .collect();
            stats(&with, &areas, |v| v.mean)
        }
        None => Value::Null,
    };
    if a.json {
        let mut s = summary;
        s["output"] = json!(a.output.display().to_string());
        outln!("{}", serde_json::to_string_pretty(&s)?)?;
    } else {
        out!("{}", text(&summary))?;
        outln!("wrote: {}", a.output.display())?;
    }
    Ok(0)
}

/// A vertex's curvatures from the kernel's `K` and `H` (`H` positive towards `p_u × p_v`; the mesh
/// convention is the opposite), the principal curvatures `H ± √(H² − K)`.
pub(crate) fn vertex_curvature(gaussian: f64, kernel_mean: f64) -> VertexCurvature {
    let mean = -kernel_mean;
    let r = (mean * mean - gaussian).max(0.0).sqrt();
    VertexCurvature {
        gaussian,
        mean,
        k1: mean + r,
        k2: mean - r,
        boundary: false,
        area: 0.0,
    }
}

/// The regular grid of a surface node (points that coincide welded, so a closed surface such as
/// a formula torus has no seam), its exact curvatures per vertex and, where the sheet is a graph
/// `z = h(x, y)` (its projection onto `xy` regular at every vertex, one orientation), `Δh`.
fn parametric(spec: &SurfaceSpec) -> Result<Parametric> {
    let sheet = spec.sheet(&NoMeshResolver)?;
    if spec.kind.derivatives(0.0, 0.0).is_none() {
        bail!(
            "{} has no rectangle parametrisation: write its mesh and give that file",
            spec.kind.name()
        );
    }
    let [ns, nt] = sheet.segments;
    let at = |s: f64, t: f64| spec.kind.derivatives(s, t).expect("checked above");
    let mesh = tessellate::regular_grid(ns + 1, nt + 1, |s, t| at(s, t).p)?;
    let mut values = Vec::with_capacity(mesh.positions.len());
    let mut lap = Vec::with_capacity(mesh.positions.len());
    let mut sign = 0.0;
    let mut graph = true;
    for i in 0..=ns {
        for j in 0..=nt {
            let d = at(i as f64 / ns as f64, j as f64 / nt as f64);
            let det = d.pu.truncate().perp_dot(d.pv.truncate());
            match laplacian::graph_laplacian(&d) {
                Some(l) if sign * det >= 0.0 => {
                    sign = det.signum();
                    lap.push(l);
                }
                _ => graph = false,
            }
            let c = d.curvature();
            values.push(vertex_curvature(c.gaussian, c.mean));
        }
    }
    let (mesh, values, lap) = weld(mesh, values, lap);
    Ok((mesh, values, graph.then_some(lap)))
}

/// A sheet, its exact curvatures and its `Δh` where it is a graph.
type Parametric = (IndexedMesh, Vec<VertexCurvature>, Option<Vec<f64>>);

/// Joins vertices whose positions agree to 10⁻⁹ of the mesh's size (the first one's values
/// stay; `lap` only when it has a value per vertex) and drops the triangles that collapse.
fn weld(
    mesh: IndexedMesh,
    values: Vec<VertexCurvature>,
    lap: Vec<f64>,
) -> (IndexedMesh, Vec<VertexCurvature>, Vec<f64>) {
    let full = lap.len() == values.len();
    let (lo, hi) = mesh.positions.iter().fold(
        (glam::DVec3::INFINITY, glam::DVec3::NEG_INFINITY),
        |(l, h), p| (l.min(*p), h.max(*p)),
    );
    let step = (1e-9 * (hi - lo).length()).max(f64::MIN_POSITIVE);
    let mut first = std::collections::HashMap::new();
    let (mut positions, mut kept, mut remap) = (Vec::new(), Vec::new(), Vec::new());
    let mut kept_lap = Vec::new();
    for (k, (p, v)) in mesh.positions.iter().zip(values).enumerate() {
        let key = ((*p - lo) / step).round().as_i64vec3().to_array();
        let id = *first.entry(key).or_insert_with(|| {
            positions.push(*p);
            kept.push(v);
            if full {
                kept_lap.push(lap[k]);
            }
            (positions.len() - 1) as u32
        });
        remap.push(id);
    }
    let triangles = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| remap[i as usize]))
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    (IndexedMesh::new(positions, triangles), kept, kept_lap)
}

/// Min, max and area-weighted mean of one curvature over the vertices that have one (interior
/// vertices with area for discrete curvatures, finite values for parametric ones).
fn stats(values: &[VertexCurvature], areas: &[f64], f: fn(&VertexCurvature) -> f64) -> Value {
    let (mut lo, mut hi, mut sum, mut weight) = (f64::INFINITY, f64::NEG_INFINITY, 0.0, 0.0);
    for (v, &a) in values.iter().zip(areas) {
        let x = f(v);
        if v.boundary || a.is_nan() || a <= 0.0 || !x.is_finite() {
            continue;
        }
        lo = lo.min(x);
        hi = hi.max(x);
        sum += x * a;
        weight += a;
    }
    if weight > 0.0 {
        json!({"min": lo, "max": hi, "mean": sum / weight})
    } else {
        json!(null)
    }
}

fn summary(
    method: &str,
    mesh: &IndexedMesh,
    values: &[VertexCurvature],
    discrete: &MeshCurvature,
) -> Value {
    let areas: Vec<f64> = discrete.vertices.iter().map(|v| v.area).collect();
    // ∫K dA: Σ K_i A_i with the mixed areas (for discrete curvatures, the total angle defect).
    let integral: f64 = values
        .iter()
        .zip(&areas)
        .filter(|(v, _)| v.gaussian.is_finite())
        .map(|(v, a)| v.gaussian * a)
        .sum();
    let chi = discrete.euler_characteristic;
    json!({
        "method": method,
        "vertices": mesh.positions.len(),
        "triangles": mesh.triangles.len(),
        "boundary_vertices": discrete.boundary_vertices,
        "skipped_vertices": discrete.skipped,
        "gaussian": stats(values, &areas, |v| v.gaussian),
        "mean": stats(values, &areas, |v| v.mean),
        "k1": stats(values, &areas, |v| v.k1),
        "k2": stats(values, &areas, |v| v.k2),
        "integral_gaussian": integral,
        "total_angle_defect": discrete.total_angle_defect,
        "euler_characteristic": chi,
        "two_pi_chi": 2.0 * std::f64::consts::PI * chi as f64,
        "gauss_bonnet_error": discrete.gauss_bonnet_error(),
    })
}

fn text(s: &Value) -> String {
    let row = |key: &str| match &s[key] {
        Value::Null => format!("{key}: no interior vertex\n"),
        v => format!(
            "{key}: min {:.6e}, max {:.6e}, area-weighted mean {:.6e}\n",
            v["min"].as_f64().unwrap_or(f64::NAN),
            v["max"].as_f64().unwrap_or(f64::NAN),
            v["mean"].as_f64().unwrap_or(f64::NAN)
        ),
    };
    let mut t = format!(
        "curvature ({}): {} vertices ({} on the boundary, {} skipped), {} triangles\n",
        s["method"].as_str().unwrap_or(""),
        s["vertices"],
        s["boundary_vertices"],
        s["skipped_vertices"],
        s["triangles"]
    );
    for key in ["gaussian", "mean", "k1", "k2"] {
        t += &row(key);
    }
    if !s["laplacian"].is_null() {
        t += &row("laplacian");
    }
    t += &format!(
        "integral of K: {:.9} (Σ K·A); angle defect {:.9} = 2πχ {:.9} with χ = {} (error {:.1e})\n",
        s["integral_gaussian"].as_f64().unwrap_or(f64::NAN),
        s["total_angle_defect"].as_f64().unwrap_or(f64::NAN),
        s["two_pi_chi"].as_f64().unwrap_or(f64::NAN),
        s["euler_characteristic"],
        s["gauss_bonnet_error"].as_f64().unwrap_or(f64::NAN)
    );
    t
}
