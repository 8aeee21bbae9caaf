//! Manifold guarantees of dual contouring on adversarial inputs: every single-cell sign pattern in
//! random neighbourhoods, random CSG trees, tangent spheres, the gyroid-sphere and a smooth union
//! of 20 spheres. Each mesh must be a closed oriented 2-manifold with the Euler characteristic and
//! shell count of the marching-cubes mesh of the same samples (dual contouring is its dual), and
//! free of self-intersections (exact count of `crate::intersect`).

use super::*;
use crate::TopologyReport;
use crate::marching_cubes::mesh_samples;
use crate::octree::mesh_sparse;
use glam::DVec3;
use solidkit_kernel::eval::{Evaluator, ZeroSide};
use solidkit_kernel::models::{SplitMix64, gyroid_sphere};
use solidkit_kernel::{Aabb, Interval, Solid};

/// Trilinear interpolation of grid samples: continuous, with the samples' signs, and a gradient.
/// An [`Evaluator`] with intervals bounded by the samples (whole-range off the grid), no pruning
/// and no zero rule of its own.
#[derive(Clone)]
pub(super) struct Trilinear<'a>(pub &'a SampleGrid);

impl Trilinear<'_> {
    /// Value and gradient at `p` (extrapolated from the nearest cell off the grid).
    fn at(&self, p: DVec3) -> (f64, DVec3) {
        let g = self.0;
        let spec = &g.spec;
        let q = (p - spec.origin) / spec.cell;
        let c = [0, 1, 2].map(|a| (q[a].floor().max(0.0) as usize).min(spec.cells[a] - 1));
        let f = [0, 1, 2].map(|a| q[a] - c[a] as f64);
        let mut v = 0.0;
        let mut d = DVec3::ZERO;
        for corner in 0..8 {
            let o = [corner & 1, corner >> 1 & 1, corner >> 2 & 1];
            let s = g.at(c[0] + o[0], c[1] + o[1], c[2] + o[2]) as f64;
            let w = |a: usize| if o[a] == 1 { f[a] } else { 1.0 - f[a] };
            let dw = |a: usize| if o[a] == 1 { 1.0 } else { -1.0 };
            v += s * w(0) * w(1) * w(2);
            d += s * DVec3::new(
                dw(0) * w(1) * w(2),
                w(0) * dw(1) * w(2),
                w(0) * w(1) * dw(2),
            );
        }
        (v, d / spec.cell)
    }
}

impl Evaluator for Trilinear<'_> {
    type BatchScratch = ();
    type PointScratch = ();
    type GradientScratch = ();
    type IntervalScratch = ();
    type ZeroScratch = ();

    fn len(&self) -> usize {
        1
    }

    fn eval_many(&self, x: &[f32], y: &[f32], z: &[f32], out: &mut [f32], _: &mut ()) {
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.at(DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64)).0 as f32;
        }
    }

    fn value_with(&self, p: DVec3, _: &mut ()) -> f64 {
        self.at(p).0
    }

    fn values_gradients(&self, pts: &[DVec3], values: &mut [f64], grads: &mut [DVec3], _: &mut ()) {
        for (k, p) in pts.iter().enumerate() {
            (values[k], grads[k]) = self.at(*p);
        }
    }

    /// The range of the samples at the corners of the cells `b` touches (a trilinear cell stays
    /// within its corners' range); the whole line where `b` leaves the grid.
    fn interval_with(&self, b: &Aabb, _: &mut ()) -> Interval {
        let spec = &self.0.spec;
        let lo = (b.min - spec.origin) / spec.cell;
        let hi = (b.max - spec.origin) / spec.cell;
        if (0..3).any(|a| !(lo[a] >= 0.0 && hi[a] <= spec.cells[a] as f64)) {
            return Interval::entire();
        }
        let range = |a: usize| lo[a].floor() as usize..=(hi[a].ceil() as usize).min(spec.cells[a]);
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        for k in range(2) {
            for j in range(1) {
                for i in range(0) {
                    let s = self.0.at(i, j, k) as f64;
                    (min, max) = (min.min(s), max.max(s));
                }
            }
        }
        Interval::new(min, max)
    }

    fn prune(&self, _: &mut ()) -> Option<Self> {
        None
    }

    fn zero_side(&self, _: DVec3, _: &mut ()) -> ZeroSide {
        ZeroSide::Surface
    }
}

#[track_caller]
pub(super) fn assert_dual_of_mc(dc: &IndexedMesh, mc: &IndexedMesh, what: &str) -> TopologyReport {
    let r = TopologyReport::of(dc);
    let m = TopologyReport::of(mc);
    assert!(
        r.closed && r.manifold && r.oriented,
        "{what}: {} boundary, {} non-manifold edges, {} non-manifold vertices, {} inconsistent: \
         {:?}",
        r.boundary_edges,
        r.non_manifold_edges,
        r.non_manifold_vertices,
        r.inconsistent_edges,
        r.examples
    );
    assert_eq!(
        (r.euler_characteristic, r.shells),
        (m.euler_characteristic, m.shells),
        "{what}: topology differs from marching cubes"
    );
    assert_eq!(r.genus_per_shell.len(), m.genus_per_shell.len(), "{what}");
    r
}

/// Meshes with self-intersecting triangle pairs: `(what, pairs, first example)`.
#[derive(Default)]
pub(super) struct Crossings(Vec<(String, usize, Option<[u32; 2]>)>);

impl Crossings {
    /// Records `r`'s self-intersections (the count must have been computed).
    pub(super) fn note(&mut self, r: &TopologyReport, what: &str) {
        let n = r.self_intersections.expect("self-intersections counted");
        if n > 0 {
            self.0.push((
                what.to_string(),
                n,
                r.examples.self_intersections.first().copied(),
            ));
        }
    }

    /// Fails listing every mesh with self-intersections.
    #[track_caller]
    pub(super) fn assert_none(&self, what: &str) {
        let pairs: usize = self.0.iter().map(|c| c.1).sum();
        assert!(
            self.0.is_empty(),
            "{what}: {} meshes with {pairs} self-intersecting pairs: {:?}",
            self.0.len(),
            &self.0[..self.0.len().min(20)]
        );
    }
}

/// All 256 sign patterns of one cell, each in 8 random neighbourhoods (random signs and
/// magnitudes on the 4³ samples around it, an outside layer beyond so the surface closes).
#[test]
fn every_cell_pattern_in_random_neighbourhoods() {
    let mut rng = SplitMix64::new(7);
    let spec = GridSpec {
        origin: DVec3::ZERO,
        cell: 0.25,
        cells: [5, 5, 5],
    };
    let mut split_polygons = 0;
    let mut crossings = Crossings::default();
    for mask in 0..256usize {
        for trial in 0..8 {
            let mut values = vec![1.0f32; spec.sample_count()];
            for k in 1..5 {
                for j in 1..5 {
                    for i in 1..5 {
                        let mut v = rng.range(0.05, 1.0) as f32;
                        let centre = [i, j, k].iter().all(|&x| x == 2 || x == 3);
                        let inside = if centre {
                            let c = (i - 2) | (j - 2) << 1 | (k - 2) << 2;
                            mask >> c & 1 == 1
                        } else {
                            rng.next_f64() < 0.5
                        };
                        if inside {
                            v = -v;
                        }
                        values[spec.index(i, j, k)] = v;
                    }
                }
            }
            let samples = SampleGrid::from_values(spec, values).unwrap();
            let field = Trilinear(&samples);
            let blocks = sources::dense_blocks(&field, &samples, 8, false);
            split_polygons +=
                contour::assemble(&blocks, &spec, 8, &super::probe::FieldProbe(&field))
                    .specials
                    .len();
            let dc = mesh_dc_samples(&field, &samples, None);
            let mc = mesh_samples(&samples);
            if mc.triangles.is_empty() {
                assert!(dc.triangles.is_empty());
                continue;
            }
            let what = format!("mask {mask} trial {trial}");
            let r = assert_dual_of_mc(&dc, &mc, &what);
            crossings.note(&r, &what);
        }
    }
    crossings.assert_none("cell patterns");
    // The split-face construction was exercised, not just present.
    assert!(split_polygons > 0);
}

fn random_solid(rng: &mut SplitMix64) -> Solid {
    let count = 2 + (rng.next_u64() % 5) as usize;
    let mut parts = Vec::new();
    for _ in 0..count {
        let c = DVec3::new(
            rng.range(-0.5, 0.5),
            rng.range(-0.5, 0.5),
            rng.range(-0.5, 0.5),
        );
        let s = match rng.next_u64() % 3 {
            0 => Solid::sphere(rng.range(0.15, 0.5)),
            1 => Solid::cuboid(DVec3::new(
                rng.range(0.1, 0.8),
                rng.range(0.1, 0.8),
                rng.range(0.1, 0.8),
            )),
            _ => Solid::cylinder(rng.range(0.1, 0.4), rng.range(0.2, 0.9)),
        };
        let axis = DVec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 1.0);
        parts.push(s.rotate(axis, rng.range(0.0, 90.0)).translate(c));
    }
    let mut acc = parts[0].clone();
    for p in &parts[1..] {
        acc = match rng.next_u64() % 5 {
            0 | 1 => acc.union(p),
            2 => acc.difference(p),
            3 => acc.intersection(p).union(&p.scale_uniform(0.5)),
            _ => acc.smooth_union(p, rng.range(0.02, 0.2)),
        };
    }
    acc
}

/// 1000 random trees of spheres, boxes, cylinders, Booleans and blends at small resolutions.
#[test]
fn random_csg_trees() {
    let mut rng = SplitMix64::new(2024);
    let mut meshed = 0;
    let mut crossings = Crossings::default();
    for tree in 0..1000 {
        let s = random_solid(&mut rng);
        let bounds = s.bbox();
        if bounds.is_empty() {
            continue;
        }
        let res = 10 + (rng.next_u64() % 15) as usize;
        let spec = GridSpec::for_bounds(&bounds, res).unwrap();
        let p = s.compile();
        let (dc, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
        let (mc, _) = mesh_sparse(&p, spec, &Default::default()).unwrap();
        if mc.triangles.is_empty() {
            assert!(dc.triangles.is_empty(), "tree {tree}");
            continue;
        }
        let what = format!("tree {tree}");
        let r = assert_dual_of_mc(&dc, &mc, &what);
        crossings.note(&r, &what);
        meshed += 1;
    }
    crossings.assert_none("random trees");
    assert!(meshed > 900, "{meshed}");
}

/// Adaptive simplification on 150 random trees: still closed, manifold, oriented and free of
/// self-intersections (the merged nodes are checked exactly and forbidden where they cross).
#[test]
fn random_csg_trees_with_tolerance() {
    let mut rng = SplitMix64::new(77);
    let mut crossings = Crossings::default();
    let mut simplified = 0;
    for tree in 0..150 {
        let s = random_solid(&mut rng);
        let bounds = s.bbox();
        if bounds.is_empty() {
            continue;
        }
        let res = 16 + (rng.next_u64() % 17) as usize;
        let spec = GridSpec::for_bounds(&bounds, res).unwrap();
        let p = s.compile();
        let (plain, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
        let opts = DcOptions {
            tolerance: Some(rng.range(0.05, 0.5) * spec.cell),
            ..DcOptions::default()
        };
        let (dc, _) = mesh_dc(&p, spec, &opts).unwrap();
        let what = format!("tree {tree}");
        let r = TopologyReport::of(&dc);
        let m = TopologyReport::of(&plain);
        assert!(
            r.closed && r.manifold && r.oriented || dc.triangles.is_empty(),
            "{what}"
        );
        assert_eq!(r.euler_characteristic, m.euler_characteristic, "{what}");
        crossings.note(&r, &what);
        simplified += usize::from(dc.triangles.len() < plain.triangles.len());
    }
    crossings.assert_none("random trees with tolerance");
    assert!(simplified > 100, "{simplified}");
}

/// Two spheres touching at one point, with the contact on a sample, an edge, a face and inside
/// a cell.
#[test]
fn tangent_spheres() {
    let s = Solid::sphere(0.5)
        .translate(DVec3::new(-0.5, 0.0, 0.0))
        .union(&Solid::sphere(0.5).translate(DVec3::new(0.5, 0.0, 0.0)));
    let p = s.compile();
    let mut crossings = Crossings::default();
    for (k, shift) in [
        DVec3::ZERO,
        DVec3::new(0.0, 0.5, 0.0),
        DVec3::new(0.0, 0.5, 0.5),
        DVec3::new(0.3, 0.2, 0.7),
    ]
    .into_iter()
    .enumerate()
    {
        let cell = 1.0 / 16.0;
        let spec = GridSpec {
            origin: DVec3::splat(-1.25) + shift * cell,
            cell,
            cells: [40, 40, 40],
        };
        let (dc, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
        let (mc, _) = mesh_sparse(&p, spec, &Default::default()).unwrap();
        let what = format!("shift {k}");
        let r = assert_dual_of_mc(&dc, &mc, &what);
        crossings.note(&r, &what);
    }
    crossings.assert_none("tangent spheres");
}

fn gyroid_sphere_at(n: usize) {
    let s = gyroid_sphere();
    let p = s.compile();
    let spec = GridSpec::covering(&solidkit_kernel::Aabb::centered(DVec3::ONE), n).unwrap();
    let (dc, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
    let (mc, _) = mesh_sparse(&p, spec, &Default::default()).unwrap();
    let r = assert_dual_of_mc(&dc, &mc, &format!("gyroid-sphere {n}"));
    eprintln!(
        "gyroid-sphere {n}³: {} triangles, {} shells, χ {}, {:?} self-intersections",
        r.faces, r.shells, r.euler_characteristic, r.self_intersections
    );
    let mut crossings = Crossings::default();
    crossings.note(&r, "gyroid-sphere");
    crossings.assert_none("gyroid-sphere");
}

#[test]
fn gyroid_sphere_128() {
    gyroid_sphere_at(128);
}

/// The 256³ figure (`--ignored`; about 20 s on two cores, most of it the exact self-intersection
/// count of 4.2 M triangles).
#[test]
#[ignore]
fn gyroid_sphere_256() {
    gyroid_sphere_at(256);
}

/// A smooth union (exp/log-like blend) of 20 random spheres.
#[test]
fn smooth_union_of_20_spheres() {
    let mut rng = SplitMix64::new(20);
    let spheres: Vec<Solid> = (0..20)
        .map(|_| {
            Solid::sphere(rng.range(0.1, 0.3)).translate(DVec3::new(
                rng.range(-0.6, 0.6),
                rng.range(-0.6, 0.6),
                rng.range(-0.6, 0.6),
            ))
        })
        .collect();
    let s = Solid::smooth_union_all(spheres, 0.1);
    let p = s.compile();
    let spec = GridSpec::for_bounds(&s.bbox(), 64).unwrap();
    let (dc, _) = mesh_dc(&p, spec, &DcOptions::default()).unwrap();
    let (mc, _) = mesh_sparse(&p, spec, &Default::default()).unwrap();
    let r = assert_dual_of_mc(&dc, &mc, "smooth union");
    let mut crossings = Crossings::default();
    crossings.note(&r, "smooth union");
    crossings.assert_none("smooth union");
}
