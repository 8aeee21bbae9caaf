//! Mesh simplification within a distance tolerance of the exact surface: quadric-ordered edge
//! collapses that keep a closed oriented 2-manifold closed, oriented, manifold, of the same genus
//! and free of self-intersections.
//!
//! Each vertex carries the quadric (the `Qef` of dual contouring) of the planes of the input
//! triangles around it; an edge's cost is the merged quadric's error at its minimiser, and edges
//! collapse cheapest first (ties: the shorter edge, then the vertex ids, so the result is the
//! same on every run and thread count: the pass is sequential). A collapse is made only when
//! (`surface.rs`, `checks.rs`):
//! - the link condition holds (the two vertices share exactly the two neighbours of the edge's
//!   triangles): the surface stays a 2-manifold of the same genus;
//! - every triangle around the merged vertex keeps a non-zero area and its orientation (normal
//!   turned by less than about 78°, or facing within about 45° of the field's gradient), and no
//!   triangle appears twice;
//! - the field (a distance bound) is within the tolerance at the merged vertex and at a lattice
//!   of samples about a cell apart (at most 16 per edge) on every such triangle, where a corner
//!   the input left farther out raises the bound near it by its excess (so the pass never makes
//!   the input worse and can remove such vertices);
//! - every witness those triangles answered for lies within the tolerance of one of them: the
//!   witnesses are the input's vertices moved onto the zero set by Newton steps, each answered
//!   for by exactly one live triangle (the distance from the surface back to the mesh);
//! - no such triangle meets another triangle beyond the vertices they share (the exact test of
//!   [`crate::intersect`], against the triangles near it in a hierarchy of hashed grids,
//!   `spatial.rs`).
//!
//! Candidate positions: the quadric's minimiser (clamped to the edge's box grown by the
//! tolerance), then the two ends; the first that passes is taken. Flat regions collapse fully:
//! a cube meshed by dual contouring ends at its 8 corners and 12 triangles.

mod checks;
mod local;
mod spatial;
mod surface;

#[cfg(test)]
mod tests;

use crate::IndexedMesh;
use crate::dual_contouring::qef::Qef;
use checks::Checker;
use glam::DVec3;
use local::LocalField;
use solidkit_kernel::Evaluator;
use spatial::Spatial;
use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};
use surface::Surface;

/// Cells per side of the cubes the field is pruned to.
const LOCAL_CELLS: f64 = 8.0;

/// Newton steps moving each input vertex onto the zero set (its witness).
const PROJECTION_STEPS: usize = 4;

/// Options of [`simplify`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimplifyOptions {
    /// Largest distance between the result and the zero set, both ways (model units).
    pub tolerance: f64,
    /// Spacing of the samples taken on new triangles (model units; the input's cell size for a
    /// mesh from a grid). At most 16 samples per edge are taken whatever the spacing.
    pub spacing: f64,
}

/// What [`simplify`] did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SimplifyStats {
    /// Edges collapsed.
    pub collapses: usize,
    /// Collapses refused by a check.
    pub refused: usize,
    /// True when the input was returned unchanged because it is not a closed oriented
    /// 2-manifold (or the tolerance is not positive).
    pub skipped: bool,
}

/// The mesh of the zero set of `field` simplified within `options.tolerance` of that zero set
/// (see the [module docs](self)). The input must be a closed oriented 2-manifold without
/// self-intersections for the guarantees to hold; any other input comes back unchanged
/// (`skipped`). `field` must be a distance bound (Lipschitz constant at most 1), as every
/// [`Program`](solidkit_kernel::Program) is.
pub fn simplify<E: Evaluator>(
    mesh: &IndexedMesh,
    field: &E,
    options: &SimplifyOptions,
) -> (IndexedMesh, SimplifyStats) {
    let mut stats = SimplifyStats::default();
    let tolerance = options.tolerance;
    let usable = tolerance > 0.0
        && tolerance.is_finite()
        && mesh.triangles.len() >= 4
        && closed_oriented_manifold(mesh);
    if !usable {
        stats.skipped = true;
        return (mesh.clone(), stats);
    }
    let spacing = if options.spacing > 0.0 && options.spacing.is_finite() {
        options.spacing
    } else {
        tolerance
    };
    let local = LocalField::new(field, spacing * LOCAL_CELLS);
    let value = |p: DVec3| local.value(p);
    let gradient = |p: DVec3| local.gradient(p);
    let witnesses = project(field, &mesh.positions, tolerance);
    let checker = Checker {
        field: &value,
        gradient: &gradient,
        witnesses: &witnesses,
        tolerance,
        spacing,
    };
    let mut run = Run::new(mesh, spacing);
    run.collapse_all(&checker, tolerance, &mut stats);
    (run.into_mesh(), stats)
}

/// The points moved onto the zero set by Newton steps along the gradient; a point whose steps
/// do not settle within a thousandth of the tolerance stays where it was.
fn project<E: Evaluator>(field: &E, points: &[DVec3], tolerance: f64) -> Vec<DVec3> {
    let mut out = points.to_vec();
    let mut scratch = E::GradientScratch::default();
    let mut values = vec![0.0; 1024];
    let mut gradients = vec![DVec3::ZERO; 1024];
    for chunk in out.chunks_mut(1024) {
        let original = chunk.to_vec();
        let n = chunk.len();
        for _ in 0..PROJECTION_STEPS {
            field.values_gradients(chunk, &mut values[..n], &mut gradients[..n], &mut scratch);
            for ((p, &f), g) in chunk.iter_mut().zip(&values).zip(&gradients) {
                let g2 = g.length_squared();
                if g2 > 1e-12 && f.is_finite() {
                    *p -= *g * (f / g2);
                }
            }
        }
        field.values_gradients(chunk, &mut values[..n], &mut gradients[..n], &mut scratch);
        for ((p, &f), o) in chunk.iter_mut().zip(&values).zip(original) {
            if !(f.abs() <= 1e-3 * tolerance && p.distance(o) <= tolerance) {
                *p = o;
            }
        }
    }
    out
}

/// A heap entry: cost, edge length², the edge, and the stamps of its ends when it was pushed.
type Entry = Reverse<(u64, u64, u32, u32, u32, u32)>;

/// The state of one simplification.
struct Run {
    surface: Surface,
    quadrics: Vec<Qef>,
    stamps: Vec<u32>,
    /// Vertices with an edge refused since their edges were last queued.
    refused: Vec<bool>,
    owned: Vec<Vec<u32>>,
    index: Spatial,
    heap: BinaryHeap<Entry>,
    live_vertices: usize,
}

impl Run {
    fn new(mesh: &IndexedMesh, spacing: f64) -> Self {
        let surface = Surface::new(mesh.positions.clone(), mesh.triangles.clone());
        let mut quadrics: Vec<Qef> = mesh.positions.iter().map(|&p| Qef::new(p)).collect();
        let mut index = Spatial::new(spacing, mesh.triangles.len());
        let mut owned = vec![Vec::new(); mesh.triangles.len()];
        let mut witnessed = vec![false; mesh.positions.len()];
        for (t, tri) in mesh.triangles.iter().enumerate() {
            let p = mesh.triangle_positions(t);
            let n = (p[1] - p[0]).cross(p[2] - p[0]).normalize_or_zero();
            let centre = (p[0] + p[1] + p[2]) / 3.0;
            for &v in tri {
                if n != DVec3::ZERO {
                    quadrics[v as usize].add(centre, n);
                }
                if !std::mem::replace(&mut witnessed[v as usize], true) {
                    owned[t].push(v);
                }
            }
            index.insert(t as u32, p);
        }
        let live_vertices = witnessed.iter().filter(|&&w| w).count();
        let mut run = Self {
            surface,
            quadrics,
            stamps: vec![0; mesh.positions.len()],
            refused: vec![false; mesh.positions.len()],
            owned,
            index,
            heap: BinaryHeap::new(),
            live_vertices,
        };
        for tri in &mesh.triangles {
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                if a < b {
                    run.push(a, b);
                }
            }
        }
        run
    }

    /// The merged quadric of an edge and its minimiser.
    fn merged(&self, a: u32, b: u32, tolerance: f64) -> (Qef, DVec3) {
        let (pa, pb) = (
            self.surface.positions[a as usize],
            self.surface.positions[b as usize],
        );
        let mut q = self.quadrics[b as usize];
        q.merge(&self.quadrics[a as usize]);
        let grow = DVec3::splat(tolerance.max(0.0));
        let (x, _) = q.solve(pa.min(pb) - grow, pa.max(pb) + grow);
        (q, x)
    }

    fn push(&mut self, a: u32, b: u32) {
        let (a, b) = (a.min(b), a.max(b));
        // Ordering only: the tolerance clamp does not change the order much.
        let (q, x) = self.merged(a, b, 0.0);
        let cost = q.error(x);
        let len =
            self.surface.positions[a as usize].distance_squared(self.surface.positions[b as usize]);
        self.heap.push(Reverse((
            cost.to_bits(),
            len.to_bits(),
            a,
            b,
            self.stamps[a as usize],
            self.stamps[b as usize],
        )));
    }

    fn collapse_all(&mut self, checker: &Checker, tolerance: f64, stats: &mut SimplifyStats) {
        let mut scratch = Vec::new();
        while let Some(Reverse((_, _, a, b, sa, sb))) = self.heap.pop() {
            if self.stamps[a as usize] != sa
                || self.stamps[b as usize] != sb
                || self.surface.around[a as usize].is_empty()
                || self.surface.around[b as usize].is_empty()
                || self.live_vertices <= 4
            {
                continue;
            }
            let Some(star) = self.surface.star(b, a) else {
                self.refuse(a, b);
                continue;
            };
            // The quadric only orders the edges and proposes a position: its planes are the
            // input's triangles, which dual contouring leaves up to a few tenths of a cell off a
            // sharp edge, so its error says nothing about the distance to the surface (refusing
            // on it kept a turned cube at 328 triangles). The checks below decide.
            let (q, x) = self.merged(a, b, tolerance);
            let pa = self.surface.positions[a as usize];
            let pb = self.surface.positions[b as usize];
            let mut candidates = [x, pa, pb];
            candidates[1..].sort_by(|u, v| q.error(*u).total_cmp(&q.error(*v)));
            let passed = candidates.iter().find_map(|&at| {
                checker
                    .check(
                        &self.surface,
                        &star,
                        at,
                        &self.owned,
                        &self.index,
                        &mut scratch,
                    )
                    .map(|p| (at, p))
            });
            let Some((at, passed)) = passed else {
                self.refuse(a, b);
                stats.refused += 1;
                continue;
            };
            for &t in star.removed.iter().chain(&star.kept) {
                self.index.remove(t);
                self.owned[t as usize].clear();
            }
            self.surface.collapse(&star, at);
            for &t in &star.kept {
                self.index.insert(t, self.surface.corners(t));
            }
            for (w, t) in passed.witnesses {
                self.owned[t as usize].push(w);
            }
            self.quadrics[a as usize] = q;
            self.live_vertices -= 1;
            stats.collapses += 1;
            // The merged vertex's edges are queued again; so are those of its neighbours that
            // had an edge refused (the collapse changed their surroundings).
            let link = self.surface.neighbours(a);
            self.stamps[a as usize] += 1;
            let retry: Vec<u32> = link
                .iter()
                .copied()
                .filter(|&w| std::mem::take(&mut self.refused[w as usize]))
                .collect();
            for &w in &retry {
                self.stamps[w as usize] += 1;
            }
            for &w in &link {
                self.push(a, w);
            }
            for &w in &retry {
                for v in self.surface.neighbours(w) {
                    if v != a {
                        self.push(w, v);
                    }
                }
            }
        }
    }

    /// Marks both ends of a refused edge.
    fn refuse(&mut self, a: u32, b: u32) {
        self.refused[a as usize] = true;
        self.refused[b as usize] = true;
    }

    /// The live vertices (in id order) and triangles (in id order).
    fn into_mesh(self) -> IndexedMesh {
        let s = self.surface;
        let mut ids = vec![u32::MAX; s.positions.len()];
        let mut positions = Vec::new();
        for (v, around) in s.around.iter().enumerate() {
            if !around.is_empty() {
                ids[v] = positions.len() as u32;
                positions.push(s.positions[v]);
            }
        }
        let triangles = s
            .triangles
            .iter()
            .zip(&s.alive)
            .filter(|(_, alive)| **alive)
            .map(|(t, _)| t.map(|v| ids[v as usize]))
            .collect();
        IndexedMesh::new(positions, triangles)
    }
}

/// True when every directed edge appears once and its reverse once (closed, oriented, manifold
/// along edges) and no triangle repeats a vertex.
fn closed_oriented_manifold(mesh: &IndexedMesh) -> bool {
    let n = mesh.positions.len();
    let mut edges: HashMap<(u32, u32), u32> = HashMap::with_capacity(mesh.triangles.len() * 3);
    for tri in &mesh.triangles {
        if !crate::usable::is_usable(tri, n) {
            return false;
        }
        for k in 0..3 {
            *edges.entry((tri[k], tri[(k + 1) % 3])).or_default() += 1;
        }
    }
    edges
        .iter()
        .all(|(&(a, b), &c)| c == 1 && edges.get(&(b, a)) == Some(&1))
}
