//! Conformance checks for any [`Evaluator`] (cargo feature `eval-tests`, as fidget exports its
//! own): public functions that panic, naming the point or box and the numbers, wherever an
//! evaluator breaks the contract of the [module docs](super). Each returns how much it checked,
//! so a caller can tell a real pass from a vacuous one.
//!
//! [`check_evaluator`] runs every check over deterministic points and boxes of a region;
//! [`check_solids`] runs it for an evaluator built from each of the [`standard_solids`] (a
//! sphere, a box with flush cutters, a smooth union, a gyroid clipped to a box, a transformed
//! cylinder). The checks one by one take the points or boxes to check at.

use super::{Evaluator, Pruned, ZeroSide, box_scale};
use crate::eval::margin;
use crate::primitive::{Gyroid, Primitive};
use crate::program::perturb::{PERTURBATION, tie_tolerance};
use crate::{Aabb, Solid};
use glam::DVec3;

/// How much a check looked at.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Checked {
    /// Points whose batch values were compared (with each other and with the scalar value).
    pub points: usize,
    /// Boxes whose interval was checked against values in them.
    pub boxes: usize,
    /// Boxes classified wholly inside or outside.
    pub classified: usize,
    /// Boxes that got a shorter evaluator (and were checked against the full one).
    pub pruned: usize,
    /// Points whose gradient was compared with central differences.
    pub gradients: usize,
    /// Near-zero points whose zero side was checked.
    pub zeros: usize,
    /// Of those, the ones settled [`ZeroSide::Inside`] or [`ZeroSide::Outside`].
    pub settled_zeros: usize,
}

impl Checked {
    /// Adds `other`'s counts.
    pub fn add(&mut self, other: &Checked) {
        self.points += other.points;
        self.boxes += other.boxes;
        self.classified += other.classified;
        self.pruned += other.pruned;
        self.gradients += other.gradients;
        self.zeros += other.zeros;
        self.settled_zeros += other.settled_zeros;
    }
}

/// Deterministic pseudo-random numbers (SplitMix64), so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn point(&mut self, b: &Aabb) -> DVec3 {
        let t = DVec3::new(self.unit(), self.unit(), self.unit());
        b.min + (b.max - b.min) * t
    }
}

/// `p` with its coordinates rounded to `f32`: the points the batch path sees exactly.
fn round_f32(p: DVec3) -> DVec3 {
    p.as_vec3().as_dvec3()
}

/// Whether two `f32` values agree exactly (equal, or both NaN; `−0 = +0`).
fn same(a: f32, b: f32) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

/// Batch values of `e` at `points` (coordinates rounded to `f32`).
fn batch<E: Evaluator>(e: &E, points: &[DVec3], s: &mut E::BatchScratch) -> Vec<f32> {
    let x: Vec<f32> = points.iter().map(|p| p.x as f32).collect();
    let y: Vec<f32> = points.iter().map(|p| p.y as f32).collect();
    let z: Vec<f32> = points.iter().map(|p| p.z as f32).collect();
    let mut out = vec![0.0; points.len()];
    e.eval_many(&x, &y, &z, &mut out, s);
    out
}

/// Points of `region`, rounded to `f32`: a lattice of 17 per axis (dyadic coordinates when the
/// region's are, so faces on them give exact zeros), then `random` uniform points.
pub fn points_in(region: &Aabb, random: usize, seed: u64) -> Vec<DVec3> {
    const N: usize = 17;
    let mut points = Vec::with_capacity(N * N * N + random);
    let size = region.max - region.min;
    for k in 0..N {
        for j in 0..N {
            for i in 0..N {
                let t = DVec3::new(i as f64, j as f64, k as f64) / (N - 1) as f64;
                points.push(round_f32(region.min + size * t));
            }
        }
    }
    let mut rng = Rng(seed);
    points.extend((0..random).map(|_| round_f32(rng.point(region))));
    points
}

/// `count` boxes in `region`: octree boxes (the region split 2 to 64 times per axis, as the
/// sparse meshers split it) alternating with boxes of random centre and half-size.
pub fn boxes_in(region: &Aabb, count: usize, seed: u64) -> Vec<Aabb> {
    let mut rng = Rng(seed);
    let size = region.max - region.min;
    (0..count)
        .map(|n| {
            if n % 2 == 0 {
                let level = 1 + (rng.next_u64() % 6) as i32;
                let cells = (1u64 << level) as f64;
                let cell = DVec3::new(rng.unit(), rng.unit(), rng.unit()) * cells;
                let lo = region.min + size * cell.floor() / cells;
                Aabb::new(lo, lo + size / cells)
            } else {
                let c = rng.point(region);
                let h = size * (0.005 + 0.2 * rng.unit());
                Aabb::new(c - h, c + h)
            }
        })
        .collect()
}

/// Boxes around `centres` (at most `count` of them, spread over the list): cubes of half-size
/// `size` times 1/16, 1/32, 1/64 or 1/128 in turn. Around zeros of the field, these are the
/// surface boxes the sparse meshers prune for.
pub fn boxes_around(centres: &[DVec3], size: f64, count: usize) -> Vec<Aabb> {
    let step = centres.len().div_ceil(count.max(1)).max(1);
    centres
        .iter()
        .step_by(step)
        .enumerate()
        .map(|(n, c)| {
            let h = size / (16 << (n % 4)) as f64;
            Aabb::new(*c - h, *c + h)
        })
        .collect()
}

/// The 27 points of the 3 × 3 × 3 lattice of `b` (corners, edge and face centres, centre) and
/// 8 random points of it.
fn box_points(b: &Aabb, rng: &mut Rng) -> Vec<DVec3> {
    let mut points: Vec<DVec3> = (0..27)
        .map(|i| {
            let t = DVec3::new((i % 3) as f64, (i / 3 % 3) as f64, (i / 9) as f64) * 0.5;
            b.min + (b.max - b.min) * t
        })
        .collect();
    points.extend((0..8).map(|_| rng.point(b)));
    points
}

/// Points where `e`'s `f64` value is (numerically) zero: bisection between consecutive points
/// of `points` of opposite sign, to a value below `10⁻¹¹` of the coordinate scale.
pub fn zeros_between<E: Evaluator>(e: &E, points: &[DVec3]) -> Vec<DVec3> {
    let mut s = E::PointScratch::default();
    let mut out = Vec::new();
    for w in points.windows(2) {
        let (mut a, mut b) = (w[0], w[1]);
        let (fa, fb) = (e.value_with(a, &mut s), e.value_with(b, &mut s));
        if !(fa < 0.0 && fb > 0.0 || fa > 0.0 && fb < 0.0) {
            continue;
        }
        let a_inside = fa < 0.0;
        for _ in 0..80 {
            let m = (a + b) * 0.5;
            let fm = e.value_with(m, &mut s);
            let tol = 1e-11 * (1.0 + m.abs().max_element());
            if fm.abs() <= tol {
                out.push(m);
                break;
            }
            if (fm < 0.0) == a_inside {
                a = m;
            } else {
                b = m;
            }
        }
    }
    out
}

/// Batch values agree with the scalar `f64` value within single-precision rounding
/// (`10⁻⁵ · (1 + max |coordinate| + |value|)`), with the values the gradient path gives (within
/// `10⁻⁹`), and do not depend on batching: the points evaluated all at once, one at a time and
/// in runs of 37 give the same `f32` values. Points are rounded to `f32` first.
pub fn check_batch<E: Evaluator>(e: &E, points: &[DVec3]) -> Checked {
    let points: Vec<DVec3> = points.iter().map(|p| round_f32(*p)).collect();
    let mut s = E::BatchScratch::default();
    let all = batch(e, &points, &mut s);
    let mut runs = Vec::with_capacity(points.len());
    for run in points.chunks(37) {
        runs.extend(batch(e, run, &mut s));
    }
    let (mut values, mut gradients) = (vec![0.0; points.len()], vec![DVec3::ZERO; points.len()]);
    e.values_gradients(
        &points,
        &mut values,
        &mut gradients,
        &mut Default::default(),
    );
    let mut ps = E::PointScratch::default();
    for (k, p) in points.iter().enumerate() {
        let alone = batch(e, &[*p], &mut s)[0];
        assert!(
            same(all[k], alone) && same(all[k], runs[k]),
            "batch value at {p} depends on batching: {} among all, {alone} alone, {} in a run",
            all[k],
            runs[k]
        );
        let v = e.value_with(*p, &mut ps);
        let b = all[k] as f64;
        let tol = 1e-5 * (1.0 + p.abs().max_element() + v.abs());
        assert!(
            (b - v).abs() <= tol || b == v || (b.is_nan() && v.is_nan()),
            "batch value {b} vs scalar {v} at {p}"
        );
        let g = values[k];
        assert!(
            (g - v).abs() <= 1e-9 * (1.0 + v.abs()) || g == v,
            "gradient path value {g} vs scalar {v} at {p}"
        );
    }
    Checked {
        points: points.len(),
        ..Checked::default()
    }
}

/// Intervals contain values: over each box, the `f64` value at each of 35 points of it lies in
/// the box's interval (up to `10⁻⁹` of the scale for rounding), and the `f32` value at the point
/// rounded to `f32` within the single-precision [`margin`].
pub fn check_intervals<E: Evaluator>(e: &E, boxes: &[Aabb]) -> Checked {
    let mut rng = Rng(0x1D7E_4A15);
    let (mut is, mut bs, mut ps) = Default::default();
    for b in boxes {
        let iv = e.interval_with(b, &mut is);
        assert!(iv.lo <= iv.hi, "empty or NaN interval {iv:?} over {b:?}");
        let scale = box_scale(b);
        let points = box_points(b, &mut rng);
        let rounded: Vec<DVec3> = points.iter().map(|p| round_f32(*p)).collect();
        let values32 = batch(e, &rounded, &mut bs);
        let m = margin(scale, iv.lo, iv.hi);
        for (p, v32) in points.iter().zip(values32) {
            let v = e.value_with(*p, &mut ps);
            let tol = 1e-9 * (scale + v.abs());
            assert!(
                iv.lo - tol <= v && v <= iv.hi + tol,
                "value {v} at {p} outside the interval {iv:?} of {b:?}"
            );
            let v32 = v32 as f64;
            assert!(
                iv.lo - m <= v32 && v32 <= iv.hi + m,
                "f32 value {v32} at {p} outside the interval {iv:?} of {b:?} (margin {m})"
            );
        }
    }
    Checked {
        boxes: boxes.len(),
        ..Checked::default()
    }
}

/// Pruning keeps values: a box classified inside (outside) has only negative (positive) `f32`
/// and `f64` values; an evaluator pruned for a box is no longer than the full one and gives the
/// same `f32` values, `f64` values (up to `10⁻¹²` relative rounding) and zero sides (at points
/// where the value is zero, found in the box) at points of the box; and pruning the pruned
/// evaluator again for an octant of the box keeps the full one's `f32` values there. One
/// interval scratch serves every box, as in the meshers.
pub fn check_pruning<E: Evaluator>(e: &E, boxes: &[Aabb]) -> Checked {
    let mut rng = Rng(0x9B0E_5EED);
    let mut is = E::IntervalScratch::default();
    let (mut bs, mut ps, mut zs) = Default::default();
    let mut checked = Checked::default();
    for b in boxes {
        let points: Vec<DVec3> = box_points(b, &mut rng)
            .into_iter()
            .map(round_f32)
            .filter(|p| b.contains(*p))
            .collect();
        let full = batch(e, &points, &mut bs);
        let pruned = match e.prune_for_box(b, &mut is) {
            class @ (Pruned::Inside | Pruned::Outside) => {
                let inside = matches!(class, Pruned::Inside);
                for (p, v32) in points.iter().zip(&full) {
                    let v = e.value_with(*p, &mut ps);
                    let signed = if inside {
                        *v32 < 0.0 && v < 0.0
                    } else {
                        *v32 > 0.0 && v > 0.0
                    };
                    assert!(
                        signed,
                        "box {b:?} classified {} but the value at {p} is {v} ({v32} in f32)",
                        if inside { "inside" } else { "outside" }
                    );
                }
                checked.classified += 1;
                continue;
            }
            Pruned::Surface(None) => continue,
            Pruned::Surface(Some(q)) => q,
        };
        checked.pruned += 1;
        assert!(
            pruned.len() <= e.len(),
            "pruning for {b:?} lengthened the evaluator: {} > {}",
            pruned.len(),
            e.len()
        );
        let short = batch(&pruned, &points, &mut bs);
        for ((p, a), c) in points.iter().zip(&full).zip(&short) {
            assert!(
                same(*a, *c),
                "pruned for {b:?}: f32 value {c} at {p}, the full evaluator's is {a}"
            );
            let (va, vc) = (e.value_with(*p, &mut ps), pruned.value_with(*p, &mut ps));
            assert!(
                va == vc || (va - vc).abs() <= 1e-12 * (1.0 + va.abs()),
                "pruned for {b:?}: f64 value {vc} at {p}, the full evaluator's is {va}"
            );
        }
        for z in zeros_between(e, &points) {
            let (a, c) = (e.zero_side(z, &mut zs), pruned.zero_side(z, &mut zs));
            assert_eq!(a, c, "pruned for {b:?}: zero side at {z}");
        }
        // Prune the pruned evaluator again, for the octant at the box's minimum.
        let octant = Aabb::new(b.min, b.center());
        let again = match pruned.prune_for_box(&octant, &mut is) {
            Pruned::Surface(Some(r)) => r,
            _ => continue,
        };
        let inner: Vec<DVec3> = points
            .iter()
            .copied()
            .filter(|p| octant.contains(*p))
            .collect();
        let (a, c) = (batch(e, &inner, &mut bs), batch(&again, &inner, &mut bs));
        for ((p, a), c) in inner.iter().zip(a).zip(c) {
            assert!(
                same(a, c),
                "pruned for {b:?} then {octant:?}: f32 value {c} at {p}, the full one's is {a}"
            );
        }
    }
    checked
}

/// Gradients are those of the values: at each point where central differences of the `f64`
/// value over steps `h` and `4h` agree and the one-sided differences nearly do (away from
/// creases and cone points), the gradient agrees with the central difference within `10⁻³`
/// relative; every gradient of a finite value is finite.
pub fn check_gradients<E: Evaluator>(e: &E, points: &[DVec3], h: f64) -> Checked {
    let (mut values, mut gradients) = (vec![0.0; points.len()], vec![DVec3::ZERO; points.len()]);
    e.values_gradients(points, &mut values, &mut gradients, &mut Default::default());
    let mut s = E::PointScratch::default();
    let mut f = |p: DVec3| e.value_with(p, &mut s);
    // Forward and backward differences along each axis.
    let mut diffs = |p: DVec3, h: f64| {
        let f0 = f(p);
        let mut axis = |d: DVec3| (f(p + d * h) - f0, f0 - f(p - d * h));
        let (x, y, z) = (axis(DVec3::X), axis(DVec3::Y), axis(DVec3::Z));
        (DVec3::new(x.0, y.0, z.0) / h, DVec3::new(x.1, y.1, z.1) / h)
    };
    let mut checked = 0;
    for ((p, v), g) in points.iter().zip(&values).zip(&gradients) {
        if !v.is_finite() {
            continue;
        }
        assert!(g.is_finite(), "gradient {g} of the value {v} at {p}");
        let ((fw, bw), (fw4, bw4)) = (diffs(*p, h), diffs(*p, 4.0 * h));
        let (fd, fd4) = ((fw + bw) * 0.5, (fw4 + bw4) * 0.5);
        let tol = 1e-5 * (1.0 + fd.length());
        if (fd - fd4).length() >= tol || (fw - bw).length() >= 1e3 * tol {
            continue; // a crease (a kink shows as one-sided differences that disagree)
        }
        assert!(
            (*g - fd).length() <= 1e-3 * (1.0 + fd.length()),
            "gradient {g} vs central difference {fd} at {p}"
        );
        checked += 1;
    }
    Checked {
        gradients: checked,
        ..Checked::default()
    }
}

/// The zero rule is consistent: at points whose value lies clearly outside the tie band
/// (twice [`tie_tolerance`]), [`Evaluator::zero_side`] gives the value's sign or
/// [`ZeroSide::Surface`]; at the near-zero points `zeros`, it depends only on the point (a fresh
/// scratch answers as a used one), and an answer `Inside` (`Outside`) has a point of that side
/// within `10⁻⁴` of the coordinate scale (along the perturbation direction or one of the 13
/// lattice axes, either way, at `10⁻⁶`, `10⁻⁵` or `10⁻⁴`).
pub fn check_zero_side<E: Evaluator>(e: &E, points: &[DVec3], zeros: &[DVec3]) -> Checked {
    let (mut zs, mut ps) = (E::ZeroScratch::default(), E::PointScratch::default());
    for p in points {
        let v = e.value_with(*p, &mut ps);
        if v.is_nan() || v.abs() <= 2.0 * tie_tolerance(*p) {
            continue;
        }
        let side = e.zero_side(*p, &mut zs);
        let sign = if v < 0.0 {
            ZeroSide::Inside
        } else {
            ZeroSide::Outside
        };
        assert!(
            side == sign || side == ZeroSide::Surface,
            "zero side {side:?} at {p}, whose value is {v}"
        );
    }
    let mut directions = vec![PERTURBATION];
    directions.extend((0..13).map(|i| {
        DVec3::new(
            (i % 3) as f64 - 1.0,
            (i / 3 % 3) as f64 - 1.0,
            (i / 9) as f64 - 1.0,
        )
        .normalize()
    }));
    let mut settled = 0;
    for z in zeros {
        let side = e.zero_side(*z, &mut zs);
        assert_eq!(
            side,
            e.zero_side(*z, &mut Default::default()),
            "zero side at {z} depends on the scratch"
        );
        let inside = match side {
            ZeroSide::Surface => continue,
            ZeroSide::Inside => true,
            ZeroSide::Outside => false,
        };
        settled += 1;
        let scale = 1.0 + z.abs().max_element();
        let found = [1e-6, 1e-5, 1e-4].iter().any(|eta| {
            directions.iter().any(|d| {
                [1.0, -1.0].iter().any(|sign| {
                    let v = e.value_with(*z + *d * (sign * eta * scale), &mut ps);
                    if inside { v < 0.0 } else { v > 0.0 }
                })
            })
        });
        assert!(
            found,
            "zero at {z} settled {side:?}, but no point of that side lies around it"
        );
    }
    Checked {
        zeros: zeros.len(),
        settled_zeros: settled,
        ..Checked::default()
    }
}

/// Every check over `region`: the lattice and 500 random points of [`points_in`]; 200 boxes of
/// [`boxes_in`] and 200 [`boxes_around`] the field's zeros; gradients with a step of `10⁻⁶` of
/// the region's size; the zero rule at the lattice's exact zeros and at zeros found between
/// consecutive points.
pub fn check_evaluator<E: Evaluator>(e: &E, region: &Aabb) -> Checked {
    let points = points_in(region, 500, 0x5EED_0001);
    let size = (region.max - region.min).max_element();
    let mut s = E::PointScratch::default();
    let mut zeros: Vec<DVec3> = points
        .iter()
        .copied()
        .filter(|p| e.value_with(*p, &mut s).abs() <= 1e-11 * (1.0 + p.abs().max_element()))
        .collect();
    zeros.extend(zeros_between(e, &points));
    let mut boxes = boxes_in(region, 200, 0x5EED_0002);
    boxes.extend(boxes_around(&zeros, size, 200));
    let mut checked = check_batch(e, &points);
    checked.add(&check_intervals(e, &boxes));
    checked.add(&check_pruning(e, &boxes));
    checked.add(&check_gradients(e, &points, 1e-6 * size));
    checked.add(&check_zero_side(e, &points, &zeros));
    checked
}

/// Test solids over the region `[-1, 1]³`, each with its name: a sphere; a cube with a corner
/// notch and a through hole, both flush with its faces (exact zeros where operands meet); a
/// smooth union of a ball and a box; a gyroid sheet clipped to a box; a cylinder rotated, scaled
/// unevenly and moved.
pub fn standard_solids() -> Vec<(&'static str, Solid)> {
    let cube = Solid::cube(1.0);
    let notch = Solid::cube(0.5).translate(DVec3::splat(0.25));
    let hole = Solid::cylinder(0.2, 1.0);
    let gyroid = Solid::primitive(Primitive::Gyroid(Gyroid { thickness: 0.3 }))
        .scale_uniform(0.25)
        .intersection(&Solid::cuboid(DVec3::new(1.5, 1.25, 1.0)));
    vec![
        ("sphere", Solid::sphere(0.75)),
        ("box difference", Solid::difference_all(cube, [notch, hole])),
        (
            "smooth union",
            Solid::sphere(0.45)
                .translate(DVec3::new(-0.35, 0.0, 0.0))
                .smooth_union(
                    &Solid::cuboid(DVec3::new(0.6, 0.5, 0.7)).translate(DVec3::new(0.35, 0.1, 0.0)),
                    0.25,
                ),
        ),
        ("gyroid in a box", gyroid),
        (
            "transformed cylinder",
            Solid::cylinder(0.3, 1.0)
                .rotate(DVec3::new(1.0, 1.0, 0.0), 35.0)
                .scale(DVec3::new(1.0, 0.7, 1.3))
                .translate(DVec3::new(0.1, -0.2, 0.05)),
        ),
    ]
}

/// [`check_evaluator`] over `[-1, 1]³` for the evaluator `build` makes of each of the
/// [`standard_solids`] (validated first); the counts per solid.
pub fn check_solids<E: Evaluator>(build: impl Fn(&Solid) -> E) -> Vec<(&'static str, Checked)> {
    let region = Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
    standard_solids()
        .into_iter()
        .map(|(name, solid)| {
            solid.validate().expect("a valid test solid");
            (name, check_evaluator(&build(&solid), &region))
        })
        .collect()
}
