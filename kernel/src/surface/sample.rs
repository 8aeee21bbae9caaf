//! A surface node's sheet as an open triangle mesh with unit vertex normals: a regular
//! `(n_s + 1) × (n_t + 1)` grid for rectangle-parametrised surfaces (counts chosen from the
//! tolerance and the second-derivative bounds, see the [module docs](super)), the barycentric grid
//! of a triangular patch, or the PN refinement of a mesh. Coincident points (seams, collapsed
//! edges, poles) are welded and the triangles they flatten dropped.

use super::error::SurfaceError;
use super::spec::{PnSource, SurfaceKind, SurfaceSpec};
use super::tensor::TensorSurface;
use crate::IndexedMesh;
use crate::patch::{pn_refine, vertex_normals};
use crate::primitive::{MeshResolver, MeshSolidError};
use glam::{DVec2, DVec3};
use std::collections::HashMap;

/// Largest number of segments along one parameter direction or triangle edge.
pub const MAX_SEGMENTS: usize = 256;

/// Segments per edge of triangular patches and PN triangles when the node gives none.
const TRIANGLE_SEGMENTS: usize = 16;
const PN_SEGMENTS: usize = 8;

/// Samples per direction of the second-derivative estimate of NURBS and formula surfaces.
const ESTIMATE_SAMPLES: usize = 65;

/// A sampled sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct Sampled {
    /// The open (or closed) welded triangle mesh, wound along the surface normal.
    pub mesh: IndexedMesh,
    /// Unit normals per vertex.
    pub normals: Vec<DVec3>,
    /// The chord error: a bound (`estimated` false) or an estimate; `None` where not computed
    /// (triangular patches, PN triangles).
    pub chord_error: Option<f64>,
    /// Whether `chord_error` is an estimate rather than a bound.
    pub estimated: bool,
    /// Segments along `(s, t)` (both the per-edge count for triangles).
    pub segments: [usize; 2],
}

/// The sheet of `spec` (PN meshes from files through `resolver`).
pub fn sample(spec: &SurfaceSpec, resolver: &dyn MeshResolver) -> Result<Sampled, SurfaceError> {
    let segments_of = |default: usize| -> Result<usize, SurfaceError> {
        let s = spec.segments.unwrap_or(default);
        if s == 0 || s > MAX_SEGMENTS {
            return Err(SurfaceError::invalid(
                "segments",
                format!("expected 1 to {MAX_SEGMENTS} segments, got {s}"),
            ));
        }
        Ok(s)
    };
    let (mesh, normals, chord, estimated, segments) = match &spec.kind {
        SurfaceKind::Triangle(t) => {
            let s = segments_of(TRIANGLE_SEGMENTS)?;
            let mesh = t
                .tessellate(s)
                .map_err(|e| SurfaceError::invalid("segments", e.to_string()))?;
            (mesh, None, None, false, [s, s])
        }
        SurfaceKind::Pn(source) => {
            let s = segments_of(PN_SEGMENTS)?;
            let (base, normals) = match source {
                PnSource::Inline {
                    vertices,
                    normals,
                    triangles,
                } => (
                    IndexedMesh::new(vertices.clone(), triangles.clone()),
                    normals.clone(),
                ),
                PnSource::File { path } => {
                    let mesh = resolver.load(path).map_err(|error| {
                        SurfaceError::Mesh(MeshSolidError::Load {
                            path: path.clone(),
                            error,
                        })
                    })?;
                    (mesh, None)
                }
            };
            if base.triangles.is_empty() {
                return Err(SurfaceError::invalid("triangles", "expected triangles"));
            }
            let mesh = pn_refine(&base, normals.as_deref(), s).map_err(|e| {
                let key = match e {
                    crate::patch::PatchError::NormalCount { .. }
                    | crate::patch::PatchError::ZeroNormal(_) => "normals",
                    crate::patch::PatchError::NonFinite { what: "vertex", .. } => "vertices",
                    _ => "triangles",
                };
                SurfaceError::invalid(key, e.to_string())
            })?;
            (mesh, None, None, false, [s, s])
        }
        kind => grid(kind, spec.tolerance, spec.adaptive)?.0,
    };
    Ok(weld(mesh, normals, chord, estimated, segments))
}

type Parts = (
    IndexedMesh,
    Option<Vec<DVec3>>,
    Option<f64>,
    bool,
    [usize; 2],
);

/// The regular grid of a rectangle-parametrised surface meeting the tolerance, or with
/// `adaptive` its curvature-adaptive tessellation ([`super::adaptive`]; the grid where the
/// surface's edges meet in a way the adaptive tree cannot follow).
/// Also returns each vertex's parameters (before welding).
pub(super) fn grid(
    kind: &SurfaceKind,
    tolerance: Option<f64>,
    adaptive: bool,
) -> Result<(Parts, Vec<DVec2>), SurfaceError> {
    let at = |s: f64, t: f64| {
        kind.derivatives(s, t)
            .expect("a rectangle-parametrised kind")
    };
    let bound = match kind {
        SurfaceKind::Bezier(p) | SurfaceKind::BSpline(p) => p.second_derivative_bounds(),
        SurfaceKind::Interpolating(p) => p.bezier().second_derivative_bounds(),
        _ => None,
    };
    let estimated = bound.is_none();
    let n = ESTIMATE_SAMPLES - 1;
    let mut m = bound.unwrap_or([0.0; 3]);
    let mut lo = DVec3::INFINITY;
    let mut hi = DVec3::NEG_INFINITY;
    for i in 0..=n {
        for j in 0..=n {
            let d = at(i as f64 / n as f64, j as f64 / n as f64);
            lo = lo.min(d.p);
            hi = hi.max(d.p);
            if estimated {
                m[0] = m[0].max(d.puu.length());
                m[1] = m[1].max(d.puv.length());
                m[2] = m[2].max(d.pvv.length());
            }
        }
    }
    if !(lo.is_finite() && hi.is_finite() && m.iter().all(|x| x.is_finite())) {
        return Err(SurfaceError::invalid(
            "z",
            "the surface is not finite over its parameter range",
        ));
    }
    let tol = match tolerance {
        Some(t) if t.is_finite() && t > 0.0 => t,
        Some(_) => {
            return Err(SurfaceError::invalid(
                "tolerance",
                "expected a positive number",
            ));
        }
        None => 1e-3 * (hi - lo).length().max(f64::MIN_POSITIVE),
    };
    let (a, b) = (m[0] + m[1], m[2] + m[1]);
    // (A/n_s² + B/n_t²)/8 ≤ tol with each half ≤ tol/2: n = ⌈√(A / (4 tol))⌉.
    let count = |c: f64| ((c / (4.0 * tol)).sqrt().ceil() as usize).clamp(4, MAX_SEGMENTS);
    let (ns, nt) = (count(a), count(b));
    if adaptive && let Some(seams) = super::adaptive::seams(&at) {
        let bezier = match kind {
            SurfaceKind::Bezier(p) => Some(p),
            SurfaceKind::Interpolating(p) => Some(p.bezier()),
            _ => None,
        };
        let third = match kind {
            SurfaceKind::BSpline(p) => third_bounds(p),
            _ => None,
        };
        let local = |lo: DVec2, hi: DVec2| -> [f64; 3] {
            let (c, h) = ((lo + hi) * 0.5, (hi - lo) * 0.5);
            if let Some(p) = bezier {
                let b = super::bezier_bounds::second_bounds(p.counts(), p.points(), lo, hi);
                return [0, 1, 2].map(|k| b[k].min(m[k]));
            }
            match third {
                // The centre's second derivatives plus the third-derivative bounds times the
                // half sizes (mean value theorem), capped by the global bounds.
                Some(t) => {
                    let d = at(c.x, c.y);
                    [
                        (d.puu.length() + t[0] * h.x + t[1] * h.y).min(m[0]),
                        (d.puv.length() + t[1] * h.x + t[2] * h.y).min(m[1]),
                        (d.pvv.length() + t[2] * h.x + t[3] * h.y).min(m[2]),
                    ]
                }
                // An estimate: the largest of 3 × 3 samples with a margin, capped by the
                // global estimate.
                None => {
                    let mut e = [0.0f64; 3];
                    for i in 0..3 {
                        for j in 0..3 {
                            let d = at(lo.x + h.x * i as f64, lo.y + h.y * j as f64);
                            e[0] = e[0].max(d.puu.length());
                            e[1] = e[1].max(d.puv.length());
                            e[2] = e[2].max(d.pvv.length());
                        }
                    }
                    [0, 1, 2].map(|k| (1.25 * e[k]).min(m[k]))
                }
            }
        };
        let t = super::adaptive::tessellate(&at, &local, tol, [ns, nt], seams);
        return Ok((
            (
                IndexedMesh::new(t.positions, t.triangles),
                Some(t.normals),
                Some(t.chord),
                estimated,
                t.finest,
            ),
            t.params,
        ));
    }
    let chord = (a / (ns * ns) as f64 + b / (nt * nt) as f64) / 8.0;
    let mut positions = Vec::with_capacity((ns + 1) * (nt + 1));
    let mut normals = Vec::with_capacity(positions.capacity());
    let mut params = Vec::with_capacity(positions.capacity());
    for i in 0..=ns {
        for j in 0..=nt {
            let d = at(i as f64 / ns as f64, j as f64 / nt as f64);
            params.push(DVec2::new(i as f64 / ns as f64, j as f64 / nt as f64));
            positions.push(d.p);
            normals.push(d.normal());
        }
    }
    let id = |i: usize, j: usize| (i * (nt + 1) + j) as u32;
    let mut triangles = Vec::with_capacity(2 * ns * nt);
    for i in 0..ns {
        for j in 0..nt {
            let (p, q, r, s) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            triangles.push([p, q, r]);
            triangles.push([p, r, s]);
        }
    }
    Ok((
        (
            IndexedMesh::new(positions, triangles),
            Some(normals),
            Some(chord),
            estimated,
            [ns, nt],
        ),
        params,
    ))
}

/// Bounds of the third derivatives `(S_sss, S_sst, S_stt, S_ttt)` over the unit square of a
/// non-rational tensor surface (`None` for NURBS).
fn third_bounds(p: &TensorSurface) -> Option<[f64; 4]> {
    Some([
        p.derivative_bound(3, 0)?,
        p.derivative_bound(2, 1)?,
        p.derivative_bound(1, 2)?,
        p.derivative_bound(0, 3)?,
    ])
}

/// Welds points that coincide to 10⁻⁹ of the mesh's size, drops triangles that collapse, and
/// gives every vertex a unit normal (the mean of the given normals welded into it, else the
/// angle-weighted normal of its triangles).
fn weld(
    mesh: IndexedMesh,
    normals: Option<Vec<DVec3>>,
    chord_error: Option<f64>,
    estimated: bool,
    segments: [usize; 2],
) -> Sampled {
    let (lo, hi) = mesh
        .positions
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), p| {
            (l.min(*p), h.max(*p))
        });
    let step = (1e-9 * (hi - lo).length()).max(f64::MIN_POSITIVE);
    let mut first: HashMap<[i64; 3], u32> = HashMap::with_capacity(mesh.positions.len());
    let mut remap = Vec::with_capacity(mesh.positions.len());
    let mut positions = Vec::new();
    let mut sums = Vec::new();
    for (k, p) in mesh.positions.iter().enumerate() {
        let key = ((*p - lo) / step).round().as_i64vec3().to_array();
        let id = *first.entry(key).or_insert_with(|| {
            positions.push(*p);
            sums.push(DVec3::ZERO);
            (positions.len() - 1) as u32
        });
        remap.push(id);
        if let Some(n) = &normals {
            sums[id as usize] += n[k];
        }
    }
    let triangles: Vec<[u32; 3]> = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| remap[i as usize]))
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    let mesh = IndexedMesh::new(positions, triangles);
    let fallback = vertex_normals(&mesh);
    let normals = sums
        .iter()
        .zip(&fallback)
        .map(|(s, f)| s.try_normalize().unwrap_or(*f))
        .collect();
    Sampled {
        mesh,
        normals,
        chord_error,
        estimated,
        segments,
    }
}
