//! Program tests: values of Booleans and transforms against closed forms, gradients against finite
//! differences, intervals containing sampled values, the distance bound of non-uniform scales,
//! sharing in lowering, batch vs scalar agreement, and bit-exact pruning.

use super::{BatchScratch, CHUNK, Instr, IntervalScratch, Pruned};
use crate::primitive::conformance::Rng;
use crate::{Aabb, Solid};
use glam::DVec3;

fn sample_tree() -> Solid {
    let body = Solid::cuboid(DVec3::new(1.6, 1.0, 0.8)).rotate(DVec3::new(1.0, 1.0, 0.0), 30.0);
    let holes = Solid::union_all([
        Solid::cylinder(0.2, 2.0),
        Solid::cylinder(0.15, 2.0)
            .rotate(DVec3::X, 90.0)
            .translate(DVec3::new(0.4, 0.0, 0.0)),
        Solid::sphere(0.3)
            .scale(DVec3::new(1.0, 2.0, 0.5))
            .translate(DVec3::new(-0.5, 0.2, 0.0)),
    ]);
    Solid::difference_all(body, [holes])
        .union(
            &Solid::torus(0.6, 0.1)
                .mirror(DVec3::new(0.0, 1.0, 1.0))
                .translate(DVec3::Z * 0.8),
        )
        .intersection(&Solid::half_space(DVec3::new(0.2, 0.0, 1.0), 0.9))
}

#[test]
fn booleans_are_min_and_max() {
    let a = Solid::sphere(1.0);
    let b = Solid::sphere(0.5).translate(DVec3::new(1.0, 0.0, 0.0));
    let p = DVec3::new(0.3, 0.4, -0.2);
    let (fa, fb) = (a.value(p), b.value(p));
    assert_eq!(a.union(&b).value(p), fa.min(fb));
    assert_eq!(a.intersection(&b).value(p), fa.max(fb));
    assert_eq!(a.difference(&b).value(p), fa.max(-fb));
    assert_eq!(
        Solid::difference_all(a.clone(), [b.clone(), b.clone()]).value(p),
        fa.max(-fb)
    );
    assert_eq!(Solid::union_all([]).value(p), f64::INFINITY);
}

#[test]
fn rigid_transforms_keep_exact_distances() {
    let s = Solid::sphere(0.5)
        .rotate(DVec3::new(0.3, 1.0, 0.2), 47.0)
        .translate(DVec3::new(1.0, 2.0, 3.0));
    let mut rng = Rng::new(11);
    for _ in 0..200 {
        let p = rng.vec(4.0);
        let exact = (p - DVec3::new(1.0, 2.0, 3.0)).length() - 0.5;
        assert!((s.compile().value(p) - exact).abs() < 1e-12);
    }
    let m = Solid::cube(1.0)
        .translate(DVec3::new(2.0, 0.0, 0.0))
        .mirror(DVec3::X);
    assert!((m.value(DVec3::new(-2.0, 0.0, 0.0)) + 0.5).abs() < 1e-12);
}

#[test]
fn lengths_of_blends_offsets_and_shells_scale_with_their_frame() {
    // A transformed node is the node's solid transformed: its blend radius, offset distance and
    // shell thickness are lengths in its own frame.
    let a = Solid::sphere(0.4).translate(DVec3::new(-0.35, 0.0, 0.0));
    let b = Solid::cube(0.6).translate(DVec3::new(0.35, 0.1, 0.0));
    let nodes = [
        a.smooth_union(&b, 0.3),
        Solid::smooth_intersection_all([a.clone(), b.clone()], 0.25),
        Solid::smooth_difference_all(a.clone(), [b.clone()], 0.2),
        a.offset(0.2),
        a.offset(-0.1),
        b.shell(0.08),
    ];
    let mut rng = Rng::new(17);
    for node in &nodes {
        let local = node.compile();
        for (factor, turn) in [(0.5, 0.0), (3.0, 40.0), (1.7, -75.0)] {
            let moved = node
                .rotate(DVec3::new(1.0, 2.0, -0.5), turn)
                .scale(DVec3::splat(factor))
                .translate(DVec3::new(0.3, -1.0, 2.0))
                .compile();
            for _ in 0..200 {
                let q = rng.vec(1.2);
                let p = DVec3::new(1.0, 2.0, -0.5).normalize().pipe_rotate(turn, q) * factor
                    + DVec3::new(0.3, -1.0, 2.0);
                let (want, got) = (factor * local.value(q), moved.value(p));
                assert!(
                    (want - got).abs() < 1e-9 * (1.0 + want.abs()),
                    "{}: {got} vs {want} at scale {factor}",
                    node.kind().name()
                );
            }
        }
    }
    // The case the cross-check found: half of a sphere of radius 1 offset by 0.2 has radius 0.6.
    let s = Solid::sphere(1.0).offset(0.2).scale(DVec3::splat(0.5));
    assert!(s.value(DVec3::new(0.6, 0.0, 0.0)).abs() < 1e-12);
}

/// Rotation of `q` by `degrees` about the unit axis `self`.
trait PipeRotate {
    fn pipe_rotate(self, degrees: f64, q: DVec3) -> DVec3;
}

impl PipeRotate for DVec3 {
    fn pipe_rotate(self, degrees: f64, q: DVec3) -> DVec3 {
        glam::DQuat::from_axis_angle(self, degrees.to_radians()) * q
    }
}

#[test]
fn non_uniform_scale_is_a_conservative_distance_bound() {
    // An ellipsoid with semi-axes (2, 1, 0.5) built from a unit sphere.
    let e = Solid::sphere(1.0)
        .scale(DVec3::new(2.0, 1.0, 0.5))
        .compile();
    let mut rng = Rng::new(5);
    for _ in 0..2000 {
        let a = rng.vec(3.0);
        let b = a + rng.vec(0.3);
        assert!(
            (e.value(a) - e.value(b)).abs() <= (a - b).length() + 1e-12,
            "not 1-Lipschitz"
        );
        // On the surface the field vanishes.
        let dir = rng.vec(1.0).normalize();
        let on = DVec3::new(2.0, 1.0, 0.5) * dir;
        assert!(e.value(on).abs() < 1e-12);
    }
    // The true distance from the origin to the surface is the smallest semi-axis.
    assert!((e.value(DVec3::ZERO) + 0.5).abs() < 1e-12);
}

#[test]
fn gradients_agree_with_finite_differences() {
    let tape = sample_tree().compile();
    let mut rng = Rng::new(9);
    let mut checked = 0;
    for _ in 0..3000 {
        let p = rng.vec(1.5);
        let h = 1e-6;
        let fd = DVec3::new(
            tape.value(p + DVec3::X * h) - tape.value(p - DVec3::X * h),
            tape.value(p + DVec3::Y * h) - tape.value(p - DVec3::Y * h),
            tape.value(p + DVec3::Z * h) - tape.value(p - DVec3::Z * h),
        ) / (2.0 * h);
        // Skip points near creases (min/max switches), where the field is not differentiable.
        let fd2 = DVec3::new(
            tape.value(p + DVec3::X * 2.0 * h) - tape.value(p - DVec3::X * 2.0 * h),
            tape.value(p + DVec3::Y * 2.0 * h) - tape.value(p - DVec3::Y * 2.0 * h),
            tape.value(p + DVec3::Z * 2.0 * h) - tape.value(p - DVec3::Z * 2.0 * h),
        ) / (4.0 * h);
        if (fd - fd2).length() > 1e-6 {
            continue;
        }
        assert!(
            (tape.gradient(p) - fd).length() < 1e-4,
            "at {p}: {} vs {fd}",
            tape.gradient(p)
        );
        checked += 1;
    }
    assert!(checked > 2500, "only {checked} smooth points");
}

#[test]
fn intervals_contain_sampled_values() {
    let tape = sample_tree().compile();
    let mut rng = Rng::new(21);
    for _ in 0..500 {
        let c = rng.vec(1.5);
        let h = rng.vec(0.4).abs();
        let b = Aabb::new(c - h, c + h);
        let iv = tape.interval(&b);
        for _ in 0..20 {
            let t = (rng.vec(1.0) + DVec3::ONE) * 0.5;
            let v = tape.value(b.min + (b.max - b.min) * t);
            assert!(
                iv.lo <= v + 1e-12 && v <= iv.hi + 1e-12,
                "{v} outside {iv:?}"
            );
        }
    }
}

#[test]
fn lowering_folds_transforms_and_shares_subtrees() {
    let ball = Solid::sphere(0.5)
        .translate(DVec3::X)
        .rotate(DVec3::Z, 30.0);
    let s = Solid::union_all([
        ball.clone(),
        ball.clone(),
        Solid::sphere(0.5)
            .translate(DVec3::X)
            .rotate(DVec3::Z, 30.0),
    ]);
    let p = s.compile();
    // Three equal balls (two by pointer, one structurally): one leaf, no Min left.
    assert!(
        matches!(p.instrs(), [Instr::Leaf { prim: 0, .. }]),
        "{:?}",
        p.instrs()
    );
    let d = Solid::difference_all(Solid::cube(1.0), [Solid::sphere(0.2), Solid::sphere(0.2)]);
    assert_eq!(d.compile().len(), 4, "{:?}", d.compile().instrs());
}

#[test]
fn registers_are_reused_along_long_chains() {
    let mut s = Solid::sphere(0.1);
    for i in 0..2000 {
        s = s.union(&Solid::sphere(0.1).translate(DVec3::new(i as f64 * 0.01, 0.0, 0.0)));
    }
    let p = s.compile();
    // The first translate is by zero: it folds into the world frame and shares the base leaf.
    assert_eq!(p.leaf_count(), 2000);
    assert!(p.register_count() <= 3, "{}", p.register_count());
}

fn grid_points(n: usize, half: f64) -> Vec<DVec3> {
    let mut pts = Vec::new();
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let t = |a: usize| -half + 2.0 * half * a as f64 / (n - 1) as f64;
                pts.push(DVec3::new(t(i), t(j), t(k)));
            }
        }
    }
    pts
}

fn batch_values(p: &super::Program, pts: &[DVec3]) -> Vec<f32> {
    let x: Vec<f32> = pts.iter().map(|q| q.x as f32).collect();
    let y: Vec<f32> = pts.iter().map(|q| q.y as f32).collect();
    let z: Vec<f32> = pts.iter().map(|q| q.z as f32).collect();
    let mut out = vec![0f32; pts.len()];
    p.eval_many(&x, &y, &z, &mut out, &mut BatchScratch::new(p));
    out
}

#[test]
fn batch_agrees_with_scalar() {
    let p = sample_tree().compile();
    let pts = grid_points(17, 1.6);
    assert!(pts.len() > 2 * CHUNK);
    let b = batch_values(&p, &pts);
    for (q, v) in pts.iter().zip(&b) {
        let exact = p.value(*q);
        assert!(
            (*v as f64 - exact).abs() < 1e-5 * (1.0 + exact.abs()),
            "{v} vs {exact} at {q}"
        );
    }
}

#[test]
fn pruned_programs_give_identical_values_inside_their_box() {
    let p = sample_tree().compile();
    let mut rng = Rng::new(31);
    let mut s = IntervalScratch::default();
    let mut pruned_some = 0;
    for _ in 0..300 {
        let c = rng.vec(1.5);
        let h = rng.vec(0.3).abs() + DVec3::splat(0.01);
        let b = Aabb::new(c - h, c + h);
        let pts: Vec<DVec3> = (0..64).map(|_| c + rng.vec(1.0) * h).collect();
        let full = batch_values(&p, &pts);
        match p.prune_for_box(&b, &mut s) {
            Pruned::Inside => assert!(full.iter().all(|v| *v < 0.0)),
            Pruned::Outside => assert!(full.iter().all(|v| *v > 0.0)),
            Pruned::Surface(q) => {
                let q = q.unwrap_or_else(|| p.clone());
                if q.len() < p.len() {
                    pruned_some += 1;
                }
                let part = batch_values(&q, &pts);
                assert_eq!(full, part, "pruned program differs in its box");
            }
        }
    }
    assert!(pruned_some > 25, "pruning rarely applies: {pruned_some}");
}

fn blend_tree() -> Solid {
    let a = Solid::sphere(0.5).translate(DVec3::new(-0.4, 0.0, 0.0));
    let b = Solid::cuboid(DVec3::new(0.6, 0.5, 0.4)).translate(DVec3::new(0.35, 0.1, 0.0));
    let body = Solid::smooth_union_all([a, b], 0.2);
    let cut = Solid::smooth_difference_all(body, [Solid::cylinder(0.12, 2.0)], 0.05);
    Solid::smooth_intersection_all([cut.shell(0.1), Solid::half_space(DVec3::Z, 0.2)], 0.03)
        .offset(0.01)
}

#[test]
fn smooth_union_is_below_min_and_equal_beyond_the_radius() {
    let a = Solid::sphere(0.5);
    let b = Solid::sphere(0.5).translate(DVec3::X * 0.8);
    let s = a.smooth_union(&b, 0.3).compile();
    let (pa, pb) = (a.compile(), b.compile());
    let mut rng = Rng::new(2);
    for _ in 0..2000 {
        let p = rng.vec(1.5);
        let (fa, fb, f) = (pa.value(p), pb.value(p), s.value(p));
        assert!(f <= fa.min(fb) + 1e-15);
        assert!(fa.min(fb) - f <= 0.3 / 4.0 + 1e-15);
        if (fa - fb).abs() >= 0.3 {
            assert_eq!(f, fa.min(fb));
        }
    }
}

#[test]
fn blends_offsets_and_shells_keep_the_distance_bound() {
    let p = blend_tree().compile();
    let mut rng = Rng::new(12);
    for _ in 0..4000 {
        let a = rng.vec(1.2);
        let b = a + rng.vec(0.2);
        assert!(
            (p.value(a) - p.value(b)).abs() <= (a - b).length() * (1.0 + 1e-9),
            "not 1-Lipschitz"
        );
    }
}

#[test]
fn blend_gradients_intervals_and_pruning_agree() {
    let p = blend_tree().compile();
    let mut rng = Rng::new(13);
    let mut checked = 0;
    for _ in 0..2000 {
        let q = rng.vec(1.0);
        let h = 1e-6;
        let fd = |h: f64| {
            DVec3::new(
                p.value(q + DVec3::X * h) - p.value(q - DVec3::X * h),
                p.value(q + DVec3::Y * h) - p.value(q - DVec3::Y * h),
                p.value(q + DVec3::Z * h) - p.value(q - DVec3::Z * h),
            ) / (2.0 * h)
        };
        let (g1, g2) = (fd(h), fd(3.0 * h));
        if (g1 - g2).length() < 1e-6 {
            assert!(
                (p.gradient(q) - g1).length() < 1e-4,
                "at {q}: {} vs {g1}",
                p.gradient(q)
            );
            checked += 1;
        }
    }
    assert!(checked > 1500, "{checked}");
    let mut s = IntervalScratch::default();
    for _ in 0..300 {
        let c = rng.vec(1.0);
        let h = rng.vec(0.25).abs() + DVec3::splat(0.005);
        let b = Aabb::new(c - h, c + h);
        let pts: Vec<DVec3> = (0..64).map(|_| c + rng.vec(1.0) * h).collect();
        let iv = p.interval(&b);
        for q in &pts {
            let v = p.value(*q);
            assert!(
                iv.lo <= v + 1e-12 && v <= iv.hi + 1e-12,
                "{v} outside {iv:?}"
            );
        }
        let full = batch_values(&p, &pts);
        if let Pruned::Surface(Some(q)) = p.prune_for_box(&b, &mut s) {
            assert_eq!(full, batch_values(&q, &pts));
        }
    }
}

#[test]
fn batch_gradients_agree_with_scalar_ones() {
    for tree in [sample_tree(), blend_tree()] {
        let p = tree.compile();
        let pts = grid_points(11, 1.4);
        assert!(pts.len() > 3 * CHUNK);
        let (mut v, mut g) = (vec![0.0; pts.len()], vec![DVec3::ZERO; pts.len()]);
        p.values_gradients(&pts, &mut v, &mut g, &mut super::GradientScratch::default());
        for (k, q) in pts.iter().enumerate() {
            let (sv, sg) = p.value_gradient_with(*q, &mut Vec::new());
            assert_eq!(v[k], sv, "value at {q}");
            assert!(
                (g[k] - sg).length() < 1e-12,
                "gradient at {q}: {} vs {sg}",
                g[k]
            );
        }
    }
}

/// Values of `p` at `pts` by every evaluator: f64 scalar, f32 batch, f64 gradient batch (values
/// must match the scalar ones bit for bit, the f32 ones within single precision), and intervals
/// over small boxes around each point containing the scalar values.
fn assert_evaluators_agree(p: &super::Program, pts: &[DVec3], what: &str) {
    let b = batch_values(p, pts);
    let (mut v, mut g) = (vec![0.0; pts.len()], vec![DVec3::ZERO; pts.len()]);
    p.values_gradients(pts, &mut v, &mut g, &mut super::GradientScratch::default());
    let mut s = IntervalScratch::default();
    for (k, q) in pts.iter().enumerate() {
        let (sv, sg) = p.value_gradient_with(*q, &mut Vec::new());
        assert!(
            sv.is_finite() && sg.is_finite(),
            "{what}: {sv}, {sg} at {q}"
        );
        assert_eq!(p.value(*q), sv, "{what}: value at {q}");
        assert_eq!(v[k], sv, "{what}: batch gradient value at {q}");
        assert!((g[k] - sg).length() < 1e-12, "{what}: gradient at {q}");
        assert!(
            (b[k] as f64 - sv).abs() < 1e-5 * (1.0 + sv.abs()),
            "{what}: f32 {} vs f64 {sv} at {q}",
            b[k]
        );
        let iv = p.interval_with(&Aabb::new(*q - 0.01, *q + 0.01), &mut s);
        assert!(iv.lo <= sv && sv <= iv.hi, "{what}: {sv} outside {iv:?}");
    }
}

#[test]
fn binary_instructions_accept_one_value_as_both_operands() {
    // Lowering simplifies min(x, x) away, but a blend of a subtree with itself, and pruned
    // programs, can give a binary instruction one value twice; liveness then gives the result
    // the operand's own register, so every evaluator must handle dst = a = b.
    use super::{Bits, Program, lower::remap};
    let base = Solid::sphere(0.8)
        .translate(DVec3::new(0.1, 0.0, 0.0))
        .lower();
    assert_eq!(base.len(), 1);
    let pts = grid_points(9, 1.2);
    for op in [
        Instr::Min(0, 0),
        Instr::Max(0, 0),
        Instr::SmoothMin(0, 0, Bits::of(0.3)),
    ] {
        // leaf, op(leaf, leaf), op of that with itself, its negation, op of that with itself.
        let instrs = vec![
            base.instrs[0],
            op,
            remap(op, |_| 1),
            Instr::Neg(2),
            remap(op, |_| 3),
        ];
        let p = Program::from_parts(instrs, base.primitives.clone(), base.frames.clone());
        assert!(p.regs.windows(2).all(|w| w[0] == w[1]), "one register");
        let f = |v: f64| match op {
            Instr::SmoothMin(_, _, r) => super::smooth_min(v, v, r.get()),
            _ => v,
        };
        for q in &pts {
            assert_eq!(p.value(*q), f(-f(f(base.value(*q)))), "{op:?} at {q}");
        }
        assert_evaluators_agree(&p, &pts, &format!("{op:?}"));
    }
    // The same through the tree: blends of a solid with itself.
    let s = Solid::sphere(0.7);
    let pts = grid_points(7, 1.2);
    for (name, t) in [
        ("smooth_union", s.smooth_union(&s, 0.1)),
        (
            "smooth_intersection",
            Solid::smooth_intersection_all([s.clone(), s.clone()], 0.1),
        ),
        (
            "smooth_difference",
            Solid::smooth_difference_all(s.clone(), [s.clone()], 0.1),
        ),
        ("union", s.union(&s)),
        ("intersection", s.intersection(&s)),
        ("difference", s.difference(&s)),
    ] {
        let p = t.lower();
        assert_evaluators_agree(&p, &pts, name);
        // Pruned programs of the same tree too.
        let mut sc = IntervalScratch::default();
        for q in &pts {
            if let Pruned::Surface(Some(pp)) =
                p.prune_for_box(&Aabb::new(*q - 0.05, *q + 0.05), &mut sc)
            {
                assert_evaluators_agree(&pp, &[*q], name);
            }
        }
    }
    let u = s.smooth_union(&s, 0.1).lower();
    assert_eq!(u.value(DVec3::ZERO), -0.7 - 0.025);
}

#[test]
fn blend_radii_below_and_above_single_precision_are_well_defined() {
    // The f32 path divides by the radius rounded to f32: a radius that rounds to zero gave 0/0
    // (NaN samples and broken meshes), one that overflows gave ∞/∞. Tiny radii are the exact
    // minimum in every evaluator, huge ones are clamped to f32::MAX.
    let a = Solid::sphere(0.5);
    let b = Solid::sphere(0.4).translate(DVec3::new(0.5, 0.0, 0.0));
    let pts = grid_points(9, 1.2);
    for r in [1e-46, 1e-40, 5e-324, f64::MIN_POSITIVE] {
        for (t, plain) in [
            (a.smooth_union(&b, r), a.union(&b)),
            (
                Solid::smooth_intersection_all([a.clone(), b.clone()], r),
                a.intersection(&b),
            ),
            (
                Solid::smooth_difference_all(a.clone(), [b.clone()], r),
                a.difference(&b),
            ),
            // Scaled down: the radius in world units is what counts.
            (
                a.smooth_union(&b, 1e-30).scale_uniform(1e-10),
                a.union(&b).scale_uniform(1e-10),
            ),
        ] {
            let (p, plain) = (t.lower(), plain.lower());
            assert_evaluators_agree(&p, &pts, &format!("radius {r}"));
            assert_eq!(batch_values(&p, &pts), batch_values(&plain, &pts));
        }
    }
    for r in [1e39, 1e300] {
        let p = a.smooth_union(&b, r).lower();
        assert_evaluators_agree(&p, &pts, &format!("radius {r}"));
        // The clamped blend: min − f32::MAX/4 where the operands are close.
        let v = p.value(DVec3::new(0.25, 0.0, 0.0));
        assert!(v < -0.2 * f32::MAX as f64, "{v}");
    }
    // A radius just above the smallest normal f32 keeps its blend.
    let r = 2.0 * f32::MIN_POSITIVE as f64;
    let p = a.smooth_union(&b, r).lower();
    assert!(p.instrs().iter().any(|i| matches!(i, Instr::SmoothMin(..))));
    assert_evaluators_agree(&p, &pts, "radius 2·f32::MIN_POSITIVE");
}
