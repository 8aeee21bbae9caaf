//! Face vertices: where a polygon's side crosses a cell face through an extra vertex instead of
//! joining the two cell vertices directly.
//!
//! - Split faces ([`super::patches`]) always get one per segment.
//! - Across an ambiguous face, or next to a cell with several patches, a dual edge is routed
//!   through one when the point where it crosses the face breaks the conditions of
//!   [`super::certify`]: strictly inside its segment's half of an ambiguous face, strictly on its
//!   patch's side of the separating planes of the cells on both sides ([`DualFace::crossing_ok`]).
//!   Both polygons sharing the dual edge decide with the same arithmetic on the same inputs, so
//!   they agree.
//!
//! A face vertex sits where the surface's tangent lines at the segment's two crossings meet in
//! the face (split faces) when that point keeps the conditions, else at the midpoint of the two
//! crossings, which always does (each crossing is strictly inside its edge, on its patch's side).

use super::block::local_edge;
use super::cells::{Cells, FaceKey};
use super::certify::EPS;
use super::patches::{
    Config, NO_PATCH, Separator, cut_corner, edge_number, face_edges, face_segment, patch_table,
};
use super::qef::Qef;
use crate::grid::GridSpec;
use crate::marching_cubes::table::{corner_offset, edge_origin};
use glam::DVec3;

/// The conditions on a point of one face: the upper face along `axis` of the lower cell.
pub(crate) struct DualFace {
    pub axis: usize,
    /// World position of the lower cell's lower corner.
    pub origin: DVec3,
    /// Separating half-spaces of the patch on each side (empty for a lone patch).
    pub lower: &'static [Separator],
    pub upper: &'static [Separator],
    /// On an ambiguous face, the corner the segment cuts off (lower cell offsets): an inside
    /// corner, or an outside one where the face joins its inside corners.
    pub corner: Option<[usize; 3]>,
}

impl DualFace {
    /// The face between `lower` (configuration, global cell) and the cell above it along `axis`,
    /// for the segment through the lower cell's edge `edge` (`edge_upper` in the upper cell's
    /// numbering).
    pub fn new(
        lower: (Config, [usize; 3]),
        upper_config: Config,
        axis: usize,
        edge: u8,
        edge_upper: u8,
        spec: &GridSpec,
    ) -> DualFace {
        let table = patch_table();
        let seps = |config: Config, e: u8| -> &'static [Separator] {
            let c = table.get(config);
            let p = c.patch_of_edge[e as usize];
            if p == NO_PATCH {
                &[]
            } else {
                &c.separators[p as usize]
            }
        };
        let ambiguous = table.get(lower.0).ambiguous >> (2 * axis + 1) & 1 == 1;
        let corner = ambiguous.then(|| corner_offset(cut_corner(lower.0, axis, 1, edge)));
        let c = lower.1;
        DualFace {
            axis,
            origin: spec.point(c[0], c[1], c[2]),
            lower: seps(lower.0, edge),
            upper: seps(upper_config, edge_upper),
            corner,
        }
    }

    /// True when `q` (cell units from the lower cell's corner, on the face) keeps the conditions.
    pub fn point_ok(&self, q: DVec3) -> bool {
        let (a1, a2) = ((self.axis + 1) % 3, (self.axis + 2) % 3);
        if !(q[a1] > EPS && q[a1] < 1.0 - EPS && q[a2] > EPS && q[a2] < 1.0 - EPS) {
            return false;
        }
        if let Some(c) = self.corner
            && (q[a1] - c[a1] as f64).abs() + (q[a2] - c[a2] as f64).abs() >= 1.0 - EPS
        {
            return false;
        }
        let mut up = q;
        up[self.axis] -= 1.0;
        self.lower.iter().all(|s| s.value(q) < -EPS)
            && self.upper.iter().all(|s| s.value(up) < -EPS)
    }

    /// True when the dual edge from `lo` (the lower cell's vertex) to `hi` crosses the face at a
    /// point keeping the conditions.
    pub fn crossing_ok(&self, lo: DVec3, hi: DVec3, cell: f64) -> bool {
        let (a, b) = ((lo - self.origin) / cell, (hi - self.origin) / cell);
        let t = (1.0 - a[self.axis]) / (b[self.axis] - a[self.axis]);
        let mut q = a + (b - a) * t;
        q[self.axis] = 1.0;
        q.is_finite() && self.point_ok(q)
    }
}

/// The crossing on the lower cell's edge `edge` of the face in `k`, from the face crossings kept
/// by the block of the lower or of the upper cell (the edge's midpoint if neither kept it).
fn crossing(k: &FaceKey, edge: u8, cells: &Cells, spec: &GridSpec) -> (DVec3, DVec3) {
    let axis = k.axis as usize;
    let (ea, o) = edge_origin(edge);
    let mut upper = k.cell;
    upper[axis] += 1;
    for (cell, lift) in [(k.cell, 0), (upper, 1)] {
        let Some(r) = cells.get(cell) else { continue };
        let b = &cells.blocks[r.block];
        let l = [0, 1, 2].map(|a| cell[a] - b.min[a]);
        let mut s = [l[0] + o[0], l[1] + o[1], l[2] + o[2]];
        s[axis] -= lift;
        let key = local_edge(s, ea);
        if let Ok(at) = b.face_crossings.binary_search_by_key(&key, |c| c.0) {
            let (_, p, n) = b.face_crossings[at];
            return (p, n);
        }
    }
    let mut a = spec.point(k.cell[0] + o[0], k.cell[1] + o[1], k.cell[2] + o[2]);
    a[ea] += 0.5 * spec.cell;
    (a, DVec3::ZERO)
}

/// Position of a face vertex (see the module docs).
pub(crate) fn face_vertex(k: &FaceKey, cells: &Cells, spec: &GridSpec) -> DVec3 {
    let table = patch_table();
    let axis = k.axis as usize;
    let r = cells
        .get(k.cell)
        .expect("face vertices lie on surface cells");
    let mut up = k.cell;
    up[axis] += 1;
    let upper = cells
        .get(up)
        .expect("face vertices lie between surface cells");
    let (lower, above) = (table.get(r.config), table.get(upper.config));
    let ambiguous = lower.ambiguous >> (2 * axis + 1) & 1 == 1;
    let edges: Vec<u8> = face_edges(axis, 1)
        .into_iter()
        .filter(|&e| lower.patch_of_edge[e as usize] != NO_PATCH)
        .filter(|&e| !ambiguous || face_segment(r.config, axis, 1, e) == k.segment)
        .collect();
    let upper_edge = |e: u8| {
        let (ea, mut o) = edge_origin(e);
        o[axis] = 0;
        edge_number(ea, o)
    };
    let face = DualFace::new(
        (r.config, k.cell),
        upper.config,
        axis,
        edges[0],
        upper_edge(edges[0]),
        spec,
    );
    let found: Vec<(DVec3, DVec3)> = edges.iter().map(|&e| crossing(k, e, cells, spec)).collect();
    let unit = |p: DVec3| (p - face.origin) / spec.cell;
    let plane = spec.point(up[0], up[1], up[2])[axis];
    let split =
        lower.split_face >> (2 * axis + 1) & 1 == 1 && above.split_face >> (2 * axis) & 1 == 1;
    if split {
        // Where the tangent lines at the two crossings meet within the face (a QEF of their
        // planes and the face plane), kept in the face.
        let lo = face.origin;
        let mut hi = lo + DVec3::splat(spec.cell);
        let mut flo = lo;
        flo[axis] = plane;
        hi[axis] = plane;
        let mut q = Qef::new(0.5 * (flo + hi));
        let mut n = DVec3::ZERO;
        n[axis] = 1.0;
        q.add(flo, n);
        for &(p, nrm) in &found {
            q.add(p, nrm);
        }
        let mut v = q.solve(flo, hi).0;
        v[axis] = plane;
        let mut x = unit(v);
        x[axis] = 1.0;
        if face.point_ok(x) {
            return v;
        }
    }
    let mut v = 0.5 * (found[0].0 + found[found.len() - 1].0);
    v[axis] = plane;
    v
}
