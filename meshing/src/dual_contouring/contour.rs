//! Global assembly: numbers the blocks' patch vertices, finds the four cells around every owned
//! crossing edge and builds its polygon: a quad certified to split into two triangles
//! ([`super::certify`]), or a polygon fanned from the edge's crossing (through face vertices where
//! a side crosses a split face or is routed, [`super::faces`]); then places the face vertices.

use super::block::{Block, OwnedEdge};
use super::cells::{CellRef, Cells, FaceKey};
use super::certify::{EPS, EdgeFrame, FaceKind, RingFace, certify};
use super::faces::{DualFace, face_vertex};
use super::patches::{Config, NO_PATCH, edge_number, face_segment, patch_table};
use super::probe::{BatchScratch, Probe, evaluate};
use crate::grid::GridSpec;
use crate::sink::extend_in_blocks;
use glam::DVec3;
use rayon::prelude::*;

/// A block's quads, its fanned polygons, and how many of its edges got no polygon.
type BlockPolygons = (Vec<Quad>, Vec<(Vec<Corner>, DVec3)>, usize);

/// A polygon corner before split-face vertices are numbered.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Corner {
    Vertex(u32),
    Face(FaceKey),
}

/// The quad of one crossing edge: cell vertices counter-clockwise seen from outside.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Quad {
    pub v: [u32; 4],
    pub normal: DVec3,
    /// Split along `v[1]`–`v[3]` (else along `v[0]`–`v[2]`).
    pub other_diagonal: bool,
}

/// A polygon fanned from a centre vertex at the edge's crossing (a quad the certificate rejected,
/// or a polygon through face vertices).
#[derive(Debug, Clone)]
pub(crate) struct Special {
    pub corners: Vec<u32>,
    pub point: DVec3,
}

/// Every vertex and polygon of a contour.
#[derive(Debug, Default)]
pub(crate) struct Contour {
    /// Cell patch vertices (block by block), then split-face vertices (the caller takes them).
    pub positions: Vec<DVec3>,
    /// First cell patch vertex of each block.
    pub bases: Vec<u32>,
    /// Quads, block by block.
    pub quads: Vec<Vec<Quad>>,
    /// Fanned polygons.
    pub specials: Vec<Special>,
    /// Owned crossing edges left without a polygon (a cell around them outside the grid): the
    /// mesh is open there and the run claims nothing ([`super::certify::claim`]).
    pub dropped: usize,
}

/// Builds the polygons of every block's owned edges and places the split-face vertices.
pub(crate) fn assemble<P: Probe>(
    blocks: &[Block],
    spec: &GridSpec,
    block_size: usize,
    probe: &P,
) -> Contour {
    let dims = spec.cells.map(|c| c.div_ceil(block_size).max(1));
    let mut bases = Vec::with_capacity(blocks.len());
    let mut count = 0u32;
    for b in blocks {
        bases.push(count);
        count += b.vertices.len() as u32;
    }
    let cells = Cells::new(blocks, dims, bases.clone(), block_size);
    let per_block: Vec<BlockPolygons> = blocks
        .par_iter()
        .enumerate()
        .map_init(BlockScratch::<P::Scratch>::default, |scratch, (bi, b)| {
            let mut quads = Vec::with_capacity(b.edges.len());
            let mut specials = Vec::new();
            let mut dropped = 0;
            // Every ring first; the folded quads' midpoints are then evaluated in batches.
            scratch.rings.clear();
            scratch.requests.clear();
            for e in &b.edges {
                let (r, fold) = ring(bi, e, &cells, spec).unwrap_or((Around::Open, None));
                if let Some(fold) = fold {
                    scratch.requests.extend(fold);
                }
                scratch.rings.push(r);
            }
            evaluate(
                probe,
                &scratch.requests,
                &mut scratch.values,
                &mut scratch.batch,
            );
            let mut values = scratch.values.iter();
            for (r, e) in scratch.rings.drain(..).zip(&b.edges) {
                match r {
                    Around::Quad(r) => {
                        let fold = r.folded.then(|| {
                            let mut next = || values.next().expect("one value per midpoint").abs();
                            (next(), next())
                        });
                        match finish(&r, fold) {
                            Some(q) => quads.push(q),
                            None => specials.push((r.ids.map(Corner::Vertex).to_vec(), e.point)),
                        }
                    }
                    Around::Fan(corners) => specials.push((corners, e.point)),
                    Around::Open => dropped += 1,
                }
            }
            (quads, specials, dropped)
        })
        .collect();
    let mut positions: Vec<DVec3> = Vec::new();
    let lens: Vec<usize> = blocks.iter().map(|b| b.vertices.len()).collect();
    extend_in_blocks(&mut positions, DVec3::ZERO, &lens, &|i, out| {
        out.copy_from_slice(&blocks[i].vertices);
    });
    let mut keys: Vec<FaceKey> = per_block
        .iter()
        .flat_map(|(_, s, _)| s.iter().flat_map(|(c, _)| c.iter()))
        .filter_map(|c| match c {
            Corner::Face(k) => Some(*k),
            Corner::Vertex(_) => None,
        })
        .collect();
    keys.sort_unstable();
    keys.dedup();
    let face_base = positions.len() as u32;
    for k in &keys {
        positions.push(face_vertex(k, &cells, spec));
    }
    let mut quads = Vec::with_capacity(blocks.len());
    let mut specials = Vec::new();
    let mut dropped = 0;
    for (q, s, d) in per_block {
        quads.push(q);
        dropped += d;
        for (corners, point) in s {
            let corners = corners
                .iter()
                .map(|c| match c {
                    Corner::Vertex(v) => *v,
                    Corner::Face(k) => {
                        face_base + keys.binary_search(k).expect("face key listed") as u32
                    }
                })
                .collect();
            specials.push(Special { corners, point });
        }
    }
    Contour {
        positions,
        bases,
        quads,
        specials,
        dropped,
    }
}

/// Buffers of one worker of [`assemble`].
#[derive(Default)]
struct BlockScratch<S> {
    rings: Vec<Around>,
    requests: Vec<(usize, DVec3)>,
    values: Vec<f64>,
    batch: BatchScratch<S>,
}

/// A crossing edge's ring of four cells that may become a quad: everything [`finish`] needs
/// (kept small: every owned edge's ring waits for the batched field values).
struct Ring {
    /// The configurations of the four cells, counter-clockwise from outside.
    configs: [Config; 4],
    /// The crossing edge's number within each cell.
    edge_in_cell: [u8; 4],
    /// Each cell's offset below the edge along the two other axes.
    around: [(u8, u8); 4],
    faces: [RingFace; 4],
    /// Vertex ids (the fan's corners, should the quad be refused) and positions.
    ids: [u32; 4],
    p: [DVec3; 4],
    frame: EdgeFrame,
    normal: DVec3,
    /// The diagonal that agrees better with the normal.
    other_diagonal: bool,
    /// A folded quad: its two diagonal midpoints are being evaluated.
    folded: bool,
}

/// A folded quad's two diagonal midpoints, each with the block whose cell holds it.
type Fold = [(usize, DVec3); 2];

/// What an owned crossing edge's ring of cells gives.
enum Around {
    /// A quad still to be certified ([`finish`]).
    Quad(Ring),
    /// A fan from the crossing through these corners (cell vertices and any face vertices).
    Fan(Vec<Corner>),
    /// A cell around the edge lies outside the grid: no polygon.
    Open,
}

/// The ring around owned edge `e` (of block `bi`), with the fold of a folded quad; `None` where
/// a cell around the edge lies outside the grid ([`Around::Open`]).
fn ring(
    bi: usize,
    e: &OwnedEdge,
    cells: &Cells,
    spec: &GridSpec,
) -> Option<(Around, Option<Fold>)> {
    let table = patch_table();
    let b = &cells.blocks[bi];
    let axis = e.axis as usize;
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    // Coordinate arrays are built whole (`map`), not patched at a computed index: a patched
    // array read back whole stalls on store forwarding.
    let g = [0, 1, 2].map(|a| b.min[a] + e.sample[a] as usize);
    if g[u] == 0 || g[v] == 0 || g[u] > spec.cells[u] || g[v] > spec.cells[v] {
        return None;
    }
    // Cells counter-clockwise around +axis; reversed when the normal points along -axis.
    let mut around = [(1u8, 1u8), (0, 1), (0, 0), (1, 0)];
    if !e.lower_inside {
        around.reverse();
    }
    // The cells' coordinates and references, as separate arrays read field by field (whole
    // `Option<(coordinates, reference)>` copies compiled to wide reloads of narrow stores).
    let mut cs = [[0usize; 3]; 4];
    let mut rs = [CellRef::default(); 4];
    let mut edge_in_cell = [0u8; 4];
    for (k, &(du, dv)) in around.iter().enumerate() {
        // (du, dv) = 1 means the cell lies below the edge along that axis.
        let o = [0, 1, 2].map(|a| {
            usize::from(if a == u {
                du
            } else if a == v {
                dv
            } else {
                0
            })
        });
        let c = [0, 1, 2].map(|a| g[a] - o[a]);
        if c[u] >= spec.cells[u] || c[v] >= spec.cells[v] || c[axis] >= spec.cells[axis] {
            return None;
        }
        let r = cells.get_near(bi, c)?;
        edge_in_cell[k] = edge_number(axis, o);
        cs[k] = c;
        rs[k] = r;
    }
    // Each cell's patches, looked up once (the table is two dependent loads).
    let pt = [0, 1, 2, 3].map(|k| table.get(rs[k].config));
    let patch = |k: usize| pt[k].patch_of_edge[edge_in_cell[k] as usize];
    let vertex = |k: usize| {
        let r = &rs[k];
        let p = patch(k);
        debug_assert_ne!(p, NO_PATCH);
        r.first + p as u32
    };
    let position = |k: usize| {
        let r = &rs[k];
        let o = &cells.blocks[r.block];
        let p = patch(k);
        o.vertices[(o.first[r.local] + p as u32) as usize]
    };
    let frame = EdgeFrame {
        origin: spec.point(g[0], g[1], g[2]),
        cell: spec.cell,
        axes: [u, v, axis],
    };
    let inside_at = |k: usize, s: [usize; 3]| {
        let c = &cs[k];
        let o = [0, 1, 2].map(|a| s[a] - c[a]);
        rs[k].config >> (o[0] | o[1] << 1 | o[2] << 2) & 1 == 1
    };
    let several = |k: usize| pt[k].edges.len() > 1;
    // At most four cell vertices and four face vertices; a vector only for fans.
    let mut corners = [Corner::Vertex(0); 8];
    let mut count = 0;
    let mut fan = false;
    let mut faces = [RingFace {
        on_x: true,
        kind: FaceKind::Far,
    }; 4];
    for k in 0..4 {
        corners[count] = Corner::Vertex(vertex(k));
        count += 1;
        let l = (k + 1) % 4;
        let (ca, cb, ra, rb) = (&cs[k], &cs[l], &rs[k], &rs[l]);
        let fa = (0..3).find(|&a| ca[a] != cb[a]).expect("neighbours");
        // The face's far corners (away from the edge, within the face).
        let w = if fa == u { v } else { u };
        let far = if ca[w] == g[w] { g[w] + 1 } else { g[w] - 1 };
        let f0 = [0, 1, 2].map(|a| if a == w { far } else { g[a] });
        let f1 = [0, 1, 2].map(|a| f0[a] + usize::from(a == axis));
        let (lower, upper, lower_k, upper_k) = if ca[fa] < cb[fa] {
            (ra, rb, k, l)
        } else {
            (rb, ra, l, k)
        };
        let lower_cell = if lower_k == k { *ca } else { *cb };
        let bit_hi = 1 << (2 * fa + 1);
        let bit_lo = 1 << (2 * fa);
        // Both cells decide the shared face alike (same four samples); the lower cell's word
        // is the one every user of the face reads.
        let (lower_pt, upper_pt) = (pt[lower_k], pt[upper_k]);
        let joined = lower_pt.joined & bit_hi != 0;
        debug_assert!(
            lower_pt.ambiguous & bit_hi == 0 || joined == (upper_pt.joined & bit_lo != 0)
        );
        let kind = FaceKind::of(
            e.lower_inside,
            !e.lower_inside,
            inside_at(k, f0),
            inside_at(k, f1),
            joined,
        );
        faces[k] = RingFace {
            on_x: fa == u,
            kind,
        };
        let ambiguous = kind.ambiguous();
        let segment = if ambiguous {
            face_segment(lower.config, fa, 1, edge_in_cell[lower_k])
        } else {
            0
        };
        let key = Corner::Face(FaceKey {
            cell: lower_cell,
            axis: fa as u8,
            segment,
        });
        if lower_pt.split_face & bit_hi != 0 && upper_pt.split_face & bit_lo != 0 {
            fan = true;
            corners[count] = key;
            count += 1;
        } else if ambiguous || several(lower_k) || several(upper_k) {
            let face = DualFace::new(
                (lower.config, lower_cell),
                upper.config,
                fa,
                edge_in_cell[lower_k],
                edge_in_cell[upper_k],
                spec,
            );
            if !face.crossing_ok(position(lower_k), position(upper_k), spec.cell) {
                fan = true;
                corners[count] = key;
                count += 1;
            }
        }
    }
    if fan {
        return Some((Around::Fan(corners[..count].to_vec()), None));
    }
    let p = [0, 1, 2, 3].map(position);
    // A folded quad: the diagonal whose midpoint lies nearer the surface keeps the crease
    // (sharp edges run along diagonals), unless that flips a triangle ([`finish`]).
    let (m0, m1) = (0.5 * (p[0] + p[2]), 0.5 * (p[1] + p[3]));
    let fold = ((m0 - m1).length() > FOLD * spec.cell).then(|| {
        [m0, m1].map(|m| {
            let c = [0, 1, 2].map(|a| {
                if a == axis {
                    g[a]
                } else {
                    let x = ((m[a] - spec.origin[a]) / spec.cell).floor();
                    x.clamp(g[a] as f64 - 1.0, g[a] as f64) as usize
                }
            });
            let r = cells
                .get_near(bi, c)
                .expect("the four cells are surface cells");
            (r.block, m)
        })
    });
    let ring = Ring {
        configs: rs.map(|r| r.config),
        edge_in_cell,
        around,
        faces,
        ids: [0, 1, 2, 3].map(vertex),
        p,
        frame,
        normal: e.normal,
        other_diagonal: better_by_normal(&p, e.normal),
        folded: fold.is_some(),
    };
    Some((Around::Quad(ring), fold))
}

/// A ring's quad, split along the diagonal whose midpoint has the smaller `|field|` (`fold`, for
/// folded quads) unless that flips a triangle, else along the one agreeing better with the
/// normal, when the certificate shows its two triangles stay clear of every other triangle;
/// else `None` (a fan from the crossing through the four cell vertices).
fn finish(r: &Ring, fold: Option<(f64, f64)>) -> Option<Quad> {
    let table = patch_table();
    let (p, [u, v, _]) = (&r.p, r.frame.axes);
    let mut other_diagonal = r.other_diagonal;
    if let Some((f0, f1)) = fold {
        let flips = |t: [[usize; 3]; 2]| {
            t.iter()
                .any(|t| agreement([p[t[0]], p[t[1]], p[t[2]]], r.normal) <= 0.0)
        };
        let by_field = f1 < f0;
        let tris = |d: bool| if d { SECOND } else { FIRST };
        if !flips(tris(by_field)) {
            other_diagonal = by_field;
        }
    }
    // Two triangles only where they provably stay clear of every other triangle; else a fan
    // from the crossing, which always does (see `certify`).
    // In cells with several patches the pieces must also keep to their patch's side.
    let seps = [0, 1, 2, 3].map(|k| {
        let c = table.get(r.configs[k]);
        c.separators[c.patch_of_edge[r.edge_in_cell[k] as usize] as usize].as_slice()
    });
    let side = |k: usize, x: DVec3| {
        // Local edge coordinates to ring cell k's unit coordinates.
        let (du, dv) = r.around[k];
        let unit = DVec3::from_array([0, 1, 2].map(|a| {
            if a == u {
                x.x + f64::from(du)
            } else if a == v {
                x.y + f64::from(dv)
            } else {
                x.z
            }
        }));
        seps[k].iter().all(|s| s.value(unit) < -EPS)
    };
    let side: Option<&dyn Fn(usize, DVec3) -> bool> = if seps.iter().any(|s| !s.is_empty()) {
        Some(&side)
    } else {
        None
    };
    certify(&p.map(|x| r.frame.local(x)), &r.faces, other_diagonal, side).then_some(Quad {
        v: r.ids,
        normal: r.normal,
        other_diagonal,
    })
}

/// Quads whose diagonal midpoints are further apart than this (in cells) are folded: their
/// diagonal is chosen on the field.
const FOLD: f64 = 0.02;

/// The two triangulations of a quad `[a, b, c, d]`: along `a`–`c`, and along `b`–`d`.
pub(crate) const FIRST: [[usize; 3]; 2] = [[0, 1, 2], [0, 2, 3]];
pub(crate) const SECOND: [[usize; 3]; 2] = [[0, 1, 3], [1, 2, 3]];

/// How well a triangle agrees with `normal` (cosine of the angle; -1 when degenerate).
pub(crate) fn agreement(t: [DVec3; 3], normal: DVec3) -> f64 {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    let len = n.length();
    if len > 0.0 && len.is_finite() {
        n.dot(normal) / len
    } else {
        -1.0
    }
}

/// True when the `b`–`d` diagonal gives triangles agreeing better with `normal` (the worse of
/// the two triangles decides).
pub(crate) fn better_by_normal(p: &[DVec3; 4], normal: DVec3) -> bool {
    let score = |t: [[usize; 3]; 2]| {
        t.iter()
            .map(|t| agreement([p[t[0]], p[t[1]], p[t[2]]], normal))
            .fold(f64::MAX, f64::min)
    };
    score(SECOND) > score(FIRST)
}
