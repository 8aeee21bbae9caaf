//! One leaf brick: sample its grid points with its pruned evaluator, then list the crossing edges
//! it owns and its cells' triangles, both grouped by grid row in the dense path's order.
//!
//! Ownership: a brick owns the edges whose lower sample lies in it — local coordinates below the
//! brick size, or up to its extent for the last brick along an axis (the grid's far faces). An edge
//! on a face shared with a culled neighbour never crosses the surface, so nothing is lost.
//! Triangle corners are stored as brick-local edge ids (16 bits); [`super::assemble`] resolves
//! the ones owned by a neighbour.

use super::control::{ClockFn, now};
use super::subdivide::Node;
use super::thin::ThinCounts;
use crate::grid::GridSpec;
use crate::marching_cubes::disjoint;
use crate::marching_cubes::pinch::{FaceRule, Pinch, PinchScratch};
use crate::marching_cubes::polygonize::loop_centre;
use crate::marching_cubes::sign::{LONE_ZERO, resolve_lone};
use crate::marching_cubes::table::{CENTRE, NO_CENTRE, case_table, edge_origin};
use crate::marching_cubes::{edge_vertex, inside, settle, snap_noise};
use glam::Vec3;
use solidkit_kernel::Evaluator;
use solidkit_kernel::eval::ZeroSide;
use std::borrow::Cow;

/// Number of distinct local edge ids (14 bits).
pub(crate) const LOCAL_EDGE_IDS: usize = 1 << 14;

/// Triangle corners from this id up are the brick's centre vertices (`id − CENTRE_IDS`-th in
/// [`BrickTriangles::centres`]); a brick has at most one per cell, far fewer than 2¹⁴.
pub(crate) const CENTRE_IDS: u16 = LOCAL_EDGE_IDS as u16;

/// Brick-local id of the edge along `axis` from local sample `(i, j, k)` (each in `0..=8`).
#[inline]
pub(crate) fn local_edge(i: usize, j: usize, k: usize, axis: usize) -> u16 {
    ((k << 10) | (j << 6) | (i << 2) | axis) as u16
}

/// Inverse of [`local_edge`].
#[inline]
pub(crate) fn local_parts(id: u16) -> ([usize; 3], usize) {
    let id = id as usize;
    ([(id >> 2) & 15, (id >> 6) & 15, id >> 10], id & 3)
}

/// What one brick contributes: views into the [`BrickStore`] of its group.
#[derive(Debug, Default)]
pub(crate) struct BrickOutput<'a> {
    /// Its vertices.
    pub edges: BrickEdges<'a>,
    /// Its triangles.
    pub triangles: BrickTriangles<'a>,
    /// Samples evaluated.
    pub samples: u64,
    /// Seconds spent evaluating the samples.
    pub evaluation_s: f64,
    /// Thin and hidden features in the brick.
    pub thin: ThinCounts,
    /// Every vertex it owns lies strictly inside its rounded grid edge and every cell with a
    /// centre vertex passed the local test ([`crate::marching_cubes::disjoint`]).
    pub certified: bool,
}

/// The crossing edges a brick owns, row by row.
#[derive(Debug, Default)]
pub(crate) struct BrickEdges<'a> {
    /// Brick coordinates (cell minimum / brick size).
    pub coord: [usize; 3],
    /// Owned sample rows per axis: lower samples with local coordinate below this are owned.
    pub owned: [usize; 3],
    /// Cells per axis in the brick.
    pub extent: [usize; 3],
    /// Owned crossing edges as (local `i << 2 | axis`, vertex), row by row (`k`, then `j`).
    pub edges: Cow<'a, [(u16, Vec3)]>,
    /// Start of each owned row `(k, j)` in `edges` (`owned[2] · owned[1] + 1` entries).
    pub edge_rows: Cow<'a, [u32]>,
}

/// A brick's triangles, row by row.
#[derive(Debug, Default)]
pub(crate) struct BrickTriangles<'a> {
    /// Triangles as brick-local corner edge ids, in cell order (`k`, `j`, `i`) then case order;
    /// ids from [`CENTRE_IDS`] up are centre vertices.
    pub triangles: Cow<'a, [[u16; 3]]>,
    /// Start of each cell row `(k, j)` in `triangles` (`extent[2] · extent[1] + 1` entries).
    pub triangle_rows: Cow<'a, [u32]>,
    /// Centre vertices of loops fanned from their centroid, in cell order.
    pub centres: Cow<'a, [Vec3]>,
    /// Start of each cell row `(k, j)` in `centres`; empty when `centres` is.
    pub centre_rows: Cow<'a, [u32]>,
}

/// The lists of a group of bricks, one after the other in each array (a brick's rows count from
/// its own start): a few allocations for the group where a list per brick grew the worker
/// threads' heaps a page at a time (one `mprotect` each, under the lock the other threads' page
/// faults take).
#[derive(Debug, Default)]
pub(crate) struct BrickStore {
    edges: Vec<(u16, Vec3)>,
    edge_rows: Vec<u32>,
    triangles: Vec<[u16; 3]>,
    triangle_rows: Vec<u32>,
    centres: Vec<Vec3>,
    centre_rows: Vec<u32>,
    bricks: Vec<BrickEntry>,
}

/// One brick of a [`BrickStore`]: its fixed fields and where its lists end.
#[derive(Debug, Clone, Copy)]
struct BrickEntry {
    coord: [usize; 3],
    owned: [usize; 3],
    extent: [usize; 3],
    /// Ends of its lists: edges, edge rows, triangles, triangle rows, centres, centre rows.
    ends: [usize; 6],
    samples: u64,
    evaluation_s: f64,
    thin: ThinCounts,
    certified: bool,
}

impl BrickStore {
    /// Empties the store, keeping its buffers.
    pub(crate) fn clear(&mut self) {
        self.edges.clear();
        self.edge_rows.clear();
        self.triangles.clear();
        self.triangle_rows.clear();
        self.centres.clear();
        self.centre_rows.clear();
        self.bricks.clear();
    }

    /// A copy with every list at its exact size (one allocation each).
    pub(crate) fn exact(&self) -> Self {
        Self {
            edges: self.edges.to_vec(),
            edge_rows: self.edge_rows.to_vec(),
            triangles: self.triangles.to_vec(),
            triangle_rows: self.triangle_rows.to_vec(),
            centres: self.centres.to_vec(),
            centre_rows: self.centre_rows.to_vec(),
            bricks: self.bricks.to_vec(),
        }
    }

    /// Where the lists end now.
    fn ends(&self) -> [usize; 6] {
        [
            self.edges.len(),
            self.edge_rows.len(),
            self.triangles.len(),
            self.triangle_rows.len(),
            self.centres.len(),
            self.centre_rows.len(),
        ]
    }

    /// The stored bricks, in the order they were processed.
    pub(crate) fn bricks(&self) -> impl Iterator<Item = BrickOutput<'_>> {
        let mut starts = [0usize; 6];
        self.bricks.iter().map(move |b| {
            let r = |i: usize| starts[i]..b.ends[i];
            let out = BrickOutput {
                edges: BrickEdges {
                    coord: b.coord,
                    owned: b.owned,
                    extent: b.extent,
                    edges: Cow::Borrowed(&self.edges[r(0)]),
                    edge_rows: Cow::Borrowed(&self.edge_rows[r(1)]),
                },
                triangles: BrickTriangles {
                    triangles: Cow::Borrowed(&self.triangles[r(2)]),
                    triangle_rows: Cow::Borrowed(&self.triangle_rows[r(3)]),
                    centres: Cow::Borrowed(&self.centres[r(4)]),
                    centre_rows: Cow::Borrowed(&self.centre_rows[r(5)]),
                },
                samples: b.samples,
                evaluation_s: b.evaluation_s,
                thin: b.thin,
                certified: b.certified,
            };
            starts = b.ends;
            out
        })
    }
}

/// Per-thread buffers reused from brick to brick.
pub(crate) struct BrickScratch<E: Evaluator> {
    samples: BoxSamples<E>,
    inside: Vec<u8>,
    batch: E::BatchScratch,
    /// Scratch of the pinch check.
    pinch: PinchScratch<E::IntervalScratch>,
    evaluation_s: f64,
    /// The lists of the bricks of the current group, copied out at their exact size when the
    /// group is done ([`BrickStore::exact`]).
    pub(crate) store: BrickStore,
}

impl<E: Evaluator> BrickScratch<E> {
    /// Empty buffers; evaluation is timed with `clock` when there is one.
    pub(crate) fn new(clock: Option<ClockFn>) -> Self {
        Self {
            samples: BoxSamples::with_clock(clock),
            inside: Vec::new(),
            batch: Default::default(),
            pinch: Default::default(),
            evaluation_s: 0.0,
            store: BrickStore::default(),
        }
    }
}

/// The sample points of a box of the grid (x fastest) and the evaluator's values there.
pub(crate) struct BoxSamples<E: Evaluator> {
    x: Vec<f32>,
    y: Vec<f32>,
    z: Vec<f32>,
    /// Values at the points, settled ([`settle`]: noise snapped, zeros signed by perturbation).
    pub values: Vec<f32>,
    /// Scratch of the symbolic inside test at zeros.
    zero_slots: E::ZeroScratch,
    /// Indices of the lone zeros of the last box sampled (see [`resolve_lone`]).
    lone: Vec<usize>,
    /// Thin and hidden features of the last box sampled ([`super::thin`]).
    pub thin: ThinCounts,
    /// Scratch of the feature search.
    interval: E::IntervalScratch,
    /// Times the evaluation, when the caller gave a clock.
    clock: Option<ClockFn>,
}

impl<E: Evaluator> BoxSamples<E> {
    /// Empty buffers; evaluation is timed with `clock` when there is one.
    pub(crate) fn with_clock(clock: Option<ClockFn>) -> Self {
        Self {
            x: Vec::new(),
            y: Vec::new(),
            z: Vec::new(),
            values: Vec::new(),
            zero_slots: Default::default(),
            lone: Vec::new(),
            thin: ThinCounts::default(),
            interval: Default::default(),
            clock,
        }
    }

    /// Samples the `n[0] × n[1] × n[2]` grid points from `min` with `program` (pruned for the
    /// box; `root` is the full evaluator, for lattice neighbours outside the box); returns the
    /// evaluation time in seconds. The one sampling rule of the sparse MC and DC paths.
    pub(crate) fn sample(
        &mut self,
        program: &E,
        root: &E,
        spec: &GridSpec,
        min: [usize; 3],
        n: [usize; 3],
        batch: &mut E::BatchScratch,
    ) -> f64 {
        for v in [&mut self.x, &mut self.y, &mut self.z] {
            v.clear();
        }
        for k in 0..n[2] {
            let zk = spec.coordinate(2, min[2] + k);
            for j in 0..n[1] {
                let yj = spec.coordinate(1, min[1] + j);
                self.x
                    .extend((0..n[0]).map(|i| spec.coordinate(0, min[0] + i)));
                self.y.extend(std::iter::repeat_n(yj, n[0]));
                self.z.extend(std::iter::repeat_n(zk, n[0]));
            }
        }
        self.values.clear();
        self.values.resize(self.x.len(), 0.0);
        let start = now(self.clock.as_ref());
        program.eval_many(&self.x, &self.y, &self.z, &mut self.values, batch);
        let seconds = now(self.clock.as_ref()) - start;
        let slots = &mut self.zero_slots;
        self.lone.clear();
        // `settle` in two passes: noise snapped over the whole box without branches, then only
        // the (rare) zeros signed one by one.
        let mut zeros = 0u8;
        snap_noise_all(&self.x, &self.y, &self.z, &mut self.values, &mut zeros);
        if zeros != 0 {
            for (i, v) in self.values.iter_mut().enumerate() {
                if *v != 0.0 {
                    continue;
                }
                *v = settle(self.x[i], self.y[i], self.z[i], *v, |p| {
                    program.zero_side(p, slots)
                });
                if *v == LONE_ZERO {
                    self.lone.push(i);
                }
            }
        }
        if !self.lone.is_empty() {
            let samples = spec.samples();
            // The rule reads samples up to two lattice steps outside the box: evaluated with the
            // program pruned for the box so grown (the same values, bit for bit, as the brick
            // that holds them samples; a long program costs far more evaluated whole).
            let mut halo: Option<Option<E>> = None;
            let interval = &mut self.interval;
            resolve_lone(&mut self.values, n, min, samples, &self.lone, |q| {
                let halo = halo.get_or_insert_with(|| halo_program(root, spec, min, n, interval));
                grid_value(halo.as_ref().unwrap_or(root), spec, q, batch)
            });
        }
        let slots = &mut self.zero_slots;
        let mut outer = |q: [usize; 3]| {
            let v = grid_value(root, spec, q, batch);
            if v != 0.0 {
                return Some(v < 0.0);
            }
            let p = [0, 1, 2].map(|a| spec.coordinate(a, q[a]) as f64);
            match root.zero_side(glam::DVec3::from(p), slots) {
                ZeroSide::Inside => Some(true),
                ZeroSide::Outside => Some(false),
                ZeroSide::Surface => None,
            }
        };
        self.thin = super::thin::scan(
            &self.values,
            n,
            min,
            spec,
            program,
            &mut self.interval,
            &mut outer,
        );
        seconds
    }
}

/// The settled-but-lone value (noise snapped, zeros left zero) of grid sample `q` by `program`:
/// single precision at the sample's single-precision coordinates, as every sampler evaluates it.
/// `root` pruned for the box of the `n` samples per axis from grid sample `min` grown by two
/// samples on every side (clamped to the grid); `None` when nothing can be cut.
fn halo_program<E: Evaluator>(
    root: &E,
    spec: &GridSpec,
    min: [usize; 3],
    n: [usize; 3],
    s: &mut E::IntervalScratch,
) -> Option<E> {
    let samples = spec.samples();
    let lo = [0, 1, 2].map(|a| f64::from(spec.coordinate(a, min[a].saturating_sub(2))));
    let hi =
        [0, 1, 2].map(|a| f64::from(spec.coordinate(a, (min[a] + n[a] + 1).min(samples[a] - 1))));
    let b = solidkit_kernel::Aabb::new(glam::DVec3::from(lo), glam::DVec3::from(hi));
    root.interval_with(&b, s);
    root.prune(s)
}

pub(crate) fn grid_value<E: Evaluator>(
    program: &E,
    spec: &GridSpec,
    q: [usize; 3],
    batch: &mut E::BatchScratch,
) -> f32 {
    let p = [0, 1, 2].map(|a| spec.coordinate(a, q[a]));
    let mut out = [0.0f32];
    program.eval_many(&[p[0]], &[p[1]], &[p[2]], &mut out, batch);
    snap_noise(p[0], p[1], p[2], out[0])
}

/// Samples the brick's points (x fastest) with its evaluator into `s.samples.values` and
/// `s.inside`.
fn sample<E: Evaluator>(
    node: &Node<E>,
    root: &E,
    spec: &GridSpec,
    n: [usize; 3],
    s: &mut BrickScratch<E>,
) {
    s.evaluation_s = s
        .samples
        .sample(&node.program, root, spec, node.min, n, &mut s.batch);
    s.inside.clear();
    s.inside
        .extend(s.samples.values.iter().map(|&v| u8::from(inside(v))));
}

/// Samples and polygonizes one brick, appending its lists to `s.store`.
pub(crate) fn process<E: Evaluator>(
    node: &Node<E>,
    root: &E,
    spec: &GridSpec,
    brick: usize,
    s: &mut BrickScratch<E>,
) {
    let e = node.extent(spec);
    let n = [e[0] + 1, e[1] + 1, e[2] + 1];
    sample(node, root, spec, n, s);
    let (nx, nxy) = (n[0], n[0] * n[1]);
    let owned = [0, 1, 2].map(|a| {
        if node.min[a] + e[a] == spec.cells[a] {
            e[a] + 1
        } else {
            brick.min(e[a])
        }
    });
    let store = &mut s.store;
    let point = |i: usize, j: usize, k: usize| {
        spec.point(node.min[0] + i, node.min[1] + j, node.min[2] + k)
    };
    let mut certified = true;
    let edge_base = store.edges.len();
    store.edge_rows.push(0);
    for k in 0..owned[2] {
        for j in 0..owned[1] {
            for i in 0..owned[0] {
                let idx = i + nx * j + nxy * k;
                let here = s.inside[idx];
                let ends = [(i + 1 < n[0], 1), (j + 1 < n[1], nx), (k + 1 < n[2], nxy)];
                for (axis, &(exists, step)) in ends.iter().enumerate() {
                    if !exists || s.inside[idx + step] == here {
                        continue;
                    }
                    let o = [
                        usize::from(axis == 0),
                        usize::from(axis == 1),
                        usize::from(axis == 2),
                    ];
                    let q = edge_vertex(
                        point(i, j, k),
                        s.samples.values[idx],
                        point(i + o[0], j + o[1], k + o[2]),
                        s.samples.values[idx + step],
                    )
                    .expect("sign change");
                    let (lo, hi) = (point(i, j, k)[axis], q[axis]);
                    let top = point(i + o[0], j + o[1], k + o[2])[axis];
                    certified &= disjoint::strictly_inside(lo, hi, top);
                    store.edges.push(((i << 2 | axis) as u16, q.as_vec3()));
                }
            }
            store.edge_rows.push((store.edges.len() - edge_base) as u32);
        }
    }
    let table = case_table();
    let rule = Pinch {
        program: root,
        spec,
        choices: node.program.has_choices(),
    };
    let corner = [0, 1, nx, nx + 1, nxy, nxy + 1, nxy + nx, nxy + nx + 1];
    // The crossing on edge `edge` of cell `(i, j, k)`, as the owner of that edge computes it.
    let crossing = |i: usize, j: usize, k: usize, edge: u8| {
        let (axis, o) = edge_origin(edge);
        let p = [i + o[0], j + o[1], k + o[2]];
        let mut q = p;
        q[axis] += 1;
        let at = |p: [usize; 3]| p[0] + nx * p[1] + nxy * p[2];
        edge_vertex(
            point(p[0], p[1], p[2]),
            s.samples.values[at(p)],
            point(q[0], q[1], q[2]),
            s.samples.values[at(q)],
        )
        .expect("a cell's triangles use crossing edges only")
    };
    let (triangle_base, centre_base) = (store.triangles.len(), store.centres.len());
    let centre_rows_start = store.centre_rows.len();
    store.triangle_rows.push(0);
    store.centre_rows.push(0);
    for k in 0..e[2] {
        for j in 0..e[1] {
            for i in 0..e[0] {
                let base = i + nx * j + nxy * k;
                let mut mask = 0usize;
                for (c, off) in corner.iter().enumerate() {
                    mask |= (s.inside[base + off] as usize) << c;
                }
                if mask == 0 || mask == 255 {
                    continue;
                }
                let cell = [node.min[0] + i, node.min[1] + j, node.min[2] + k];
                let config = table.cell_config_with(
                    mask,
                    |c| s.samples.values[base + corner[c as usize]],
                    |bit, corners, values| rule.joined(cell, bit, corners, values, &mut s.pinch),
                );
                let centre = table.centre_loop[config];
                let mut centre_at = glam::DVec3::ZERO;
                if centre != NO_CENTRE {
                    let l = &table.loops(config)[centre as usize];
                    let c = loop_centre(l.iter().map(|&edge| crossing(i, j, k, edge)));
                    store.centres.push(c.as_vec3());
                    centre_at = c;
                }
                let tris = table.triangles(config);
                if tris.len() > disjoint::PROVEN_TRIANGLES {
                    // Beyond what the table test proves for any crossings: test the cell.
                    certified &=
                        disjoint::cell_disjoint(tris, centre_at, |edge| crossing(i, j, k, edge));
                }
                let centres = store.centres.len() - centre_base;
                for tri in tris {
                    store.triangles.push(tri.map(|edge| {
                        if edge == CENTRE {
                            return CENTRE_IDS + (centres - 1) as u16;
                        }
                        let (axis, o) = edge_origin(edge);
                        local_edge(i + o[0], j + o[1], k + o[2], axis)
                    }));
                }
            }
            store
                .triangle_rows
                .push((store.triangles.len() - triangle_base) as u32);
            store
                .centre_rows
                .push((store.centres.len() - centre_base) as u32);
        }
    }
    // The common case keeps no row table (an empty table means no centre in any row).
    if store.centres.len() == centre_base {
        store.centre_rows.truncate(centre_rows_start);
    }
    let ends = store.ends();
    store.bricks.push(BrickEntry {
        coord: node.min.map(|m| m / brick),
        owned,
        extent: e,
        ends,
        samples: s.samples.values.len() as u64,
        evaluation_s: s.evaluation_s,
        thin: s.samples.thin,
        certified,
    });
}

solidkit_kernel::wide_loop! {
    /// [`snap_noise`] of every value in place; `zeros` nonzero when one became (or was) zero.
    fn snap_noise_all(x: &[f32], y: &[f32], z: &[f32], values: &mut [f32], zeros: &mut u8) {
        let mut any = 0u8;
        for (((v, &x), &y), &z) in values.iter_mut().zip(x).zip(y).zip(z) {
            let s = snap_noise(x, y, z, *v);
            any |= u8::from(s == 0.0);
            *v = s;
        }
        *zeros = any;
    }
}
