//! The swept volume's sampling against a brute-force minimum over a fine parameter grid.

use super::motion::Motion;
use super::*;
use crate::curve::{Bezier, Curve, Nurbs};
use glam::DVec3;

fn bezier(points: &[[f64; 3]]) -> Parametric {
    let pts = points.iter().map(|p| DVec3::from_array(*p)).collect();
    Parametric::Curve(Curve::Bezier(Bezier::new(pts).expect("bezier")))
}

/// A deterministic pseudo-random number in [0, 1).
fn rand(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// Checks `f ≤ f_N` at random points and `f_N − τ/2 ≤ f` where the minimising child point lies
/// in the child's box, with `f` the minimum over 20 001 parameters and the copies' own.
fn check_bound(child: &Solid, path: &Parametric, frame: SweptFrame, tolerance: f64) -> usize {
    let swept = swept_volume(child, path, frame, Some(tolerance)).expect("swept");
    let program = swept.solid.lower();
    let child_program = child.lower();
    let motion = Motion::new(path, frame);
    let (t0, t1) = path.domain();
    let n = 20_000;
    let mut ts: Vec<f64> = (0..=n)
        .map(|i| t0 + (t1 - t0) * i as f64 / n as f64)
        .collect();
    ts.extend(&swept.params);
    let maps: Vec<DAffine3> = ts.iter().map(|&t| motion.at(t).inverse()).collect();
    let bbox = child.bbox();
    let world = swept.solid.bbox().expanded(0.5);
    let mut state = 7u64;
    let mut checked = 0;
    for i in 0..400 {
        let mut r = || DVec3::new(rand(&mut state), rand(&mut state), rand(&mut state));
        // Half the points anywhere, half near the solid: a point of the child's box placed at a
        // random parameter, moved by up to a tenth of the box.
        let x = if i % 2 == 0 {
            world.min + (world.max - world.min) * r()
        } else {
            let t = t0 + (t1 - t0) * r().x;
            let q = bbox.min + (bbox.max - bbox.min) * r();
            motion.at(t).transform_point3(q) + (r() - 0.5) * 0.2 * bbox.size().length()
        };
        let (mut f, mut arg) = (f64::INFINITY, DVec3::ZERO);
        for m in &maps {
            let q = m.transform_point3(x);
            let v = child_program.value(q);
            if v < f {
                (f, arg) = (v, q);
            }
        }
        let f_n = program.value(x);
        assert!(f <= f_n + 1e-9, "f = {f} above f_N = {f_n} at {x}");
        if bbox.expanded(1e-9).contains(arg) {
            checked += 1;
            assert!(
                f_n - tolerance / 2.0 <= f + 1e-9,
                "f_N = {f_n} more than τ/2 = {} above f = {f} at {x}",
                tolerance / 2.0
            );
        }
    }
    checked
}

#[test]
fn field_bound_holds_for_a_sphere_along_a_bezier_with_rmf() {
    let path = bezier(&[
        [0.0, 0.0, 0.0],
        [3.0, 0.0, 1.0],
        [3.0, 3.0, -1.0],
        [0.0, 3.0, 2.0],
    ]);
    let checked = check_bound(&Solid::sphere(0.5), &path, SweptFrame::Rmf, 0.2);
    assert!(
        checked > 20,
        "only {checked} points had their minimiser in the box"
    );
}

#[test]
fn field_bound_holds_for_an_off_centre_box_turning_along_a_bezier() {
    // The box sits away from its origin, so turning moves it: the radius about the origin
    // enters the bound.
    let child = Solid::cuboid(DVec3::new(1.0, 0.4, 0.3)).translate(DVec3::new(0.8, 0.0, 0.0));
    let path = bezier(&[
        [0.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [2.0, 2.0, 2.0],
        [-1.0, 2.0, 0.0],
    ]);
    let checked = check_bound(&child, &path, SweptFrame::Rmf, 0.15);
    assert!(
        checked > 20,
        "only {checked} points had their minimiser in the box"
    );
    let fixed = check_bound(&child, &path, SweptFrame::Fixed, 0.15);
    assert!(
        fixed > 20,
        "only {fixed} points had their minimiser in the box"
    );
}

#[test]
fn copies_are_spaced_by_the_tolerance_along_a_line() {
    // A fixed frame along a straight segment of length 4: the copies move by at most τ between
    // consecutive parameters (the bound is exact here: 40 steps of τ).
    let path = bezier(&[[0.0, 0.0, 0.0], [4.0, 0.0, 0.0]]);
    let s = swept_volume(&Solid::sphere(1.0), &path, SweptFrame::Fixed, Some(0.1)).expect("ok");
    let pts: Vec<f64> = s.params.iter().map(|&t| path.point(t).x).collect();
    for w in pts.windows(2) {
        assert!(w[1] - w[0] <= 0.1 + 1e-12, "gap {}", w[1] - w[0]);
    }
    assert_eq!(pts[0], 0.0);
    assert_eq!(*pts.last().expect("last"), 4.0);
    assert!((41..=50).contains(&pts.len()), "{} copies", pts.len());
}

#[test]
fn rmf_turns_the_child_around_a_circle_and_closes() {
    let path = Parametric::Curve(Curve::Nurbs(
        Nurbs::circle(DVec3::ZERO, 3.0).expect("circle"),
    ));
    let motion = Motion::new(&path, SweptFrame::Rmf);
    let (t0, t1) = path.domain();
    // Half-way round a planar circle the frame has turned by π about z.
    let tm = 0.5 * (t0 + t1);
    let start = path.point(t0);
    let half = path.point(tm);
    let r = motion.rotation(tm);
    let turned = r * (start - DVec3::ZERO);
    assert!((turned - half).length() < 1e-6, "{turned} vs {half}");
    // Back at the end the frame is the start frame again.
    let end = motion.rotation(t1);
    assert!((end.x_axis - DVec3::X).length() < 1e-6, "{end}");
}

#[test]
fn errors_are_clear() {
    let path = bezier(&[[0.0, 0.0, 0.0], [100.0, 0.0, 0.0]]);
    let e = swept_volume(&Solid::sphere(1.0), &path, SweptFrame::Rmf, Some(1e-4)).unwrap_err();
    let SweptError::TooManyCopies { minimum, .. } = e else {
        panic!("{e}");
    };
    assert!(swept_volume(&Solid::sphere(1.0), &path, SweptFrame::Rmf, Some(minimum)).is_ok());
    let e = swept_volume(&Solid::sphere(1.0), &path, SweptFrame::Rmf, Some(-1.0)).unwrap_err();
    assert_eq!(e, SweptError::Tolerance(-1.0));
    // Nested swept volumes multiply the tree: refused, not lowered for minutes.
    let inner = swept_volume(&Solid::sphere(1.0), &path, SweptFrame::Rmf, Some(0.05)).expect("ok");
    assert!(inner.params.len() > 2000, "{}", inner.params.len());
    let outer = bezier(&[[0.0, 0.0, 0.0], [0.0, 0.0, 1000.0]]);
    let e = swept_volume(&inner.solid, &outer, SweptFrame::Fixed, None).unwrap_err();
    assert!(matches!(e, SweptError::TooLarge { .. }), "{e}");
    let plane = Solid::half_space(DVec3::Z, 0.0);
    let e = swept_volume(&plane, &path, SweptFrame::Rmf, None).unwrap_err();
    assert_eq!(e, SweptError::UnboundedChild);
}

#[test]
fn default_tolerance_follows_the_child() {
    let path = bezier(&[[0.0, 0.0, 0.0], [10.0, 0.0, 0.0]]);
    let s = swept_volume(&Solid::sphere(1.0), &path, SweptFrame::Fixed, None).expect("ok");
    assert_eq!(s.tolerance, default_tolerance(2.0 * 3f64.sqrt()));
}

/// Between consecutive copies, every corner of the child's box (where the travel of a box point
/// is largest: it is convex in the point) is within `τ/2` of one of the two copies' positions.
fn check_travel(child: &Solid, path: &Parametric, frame: SweptFrame, tolerance: f64) -> f64 {
    let swept = swept_volume(child, path, frame, Some(tolerance)).expect("swept");
    let motion = Motion::new(path, frame);
    let b = child.bbox();
    let corners: Vec<DVec3> = (0..8)
        .map(|i| {
            DVec3::new(
                if i & 1 == 0 { b.min.x } else { b.max.x },
                if i & 2 == 0 { b.min.y } else { b.max.y },
                if i & 4 == 0 { b.min.z } else { b.max.z },
            )
        })
        .collect();
    let mut worst = 0.0f64;
    for w in swept.params.windows(2) {
        let (ma, mb) = (motion.at(w[0]), motion.at(w[1]));
        for j in 1..32 {
            let m = motion.at(w[0] + (w[1] - w[0]) * j as f64 / 32.0);
            for &p in &corners {
                let x = m.transform_point3(p);
                let d = (x - ma.transform_point3(p))
                    .length()
                    .min((x - mb.transform_point3(p)).length());
                worst = worst.max(d);
            }
        }
    }
    assert!(
        worst <= tolerance / 2.0,
        "a corner is {worst} from both copies (τ/2 = {})",
        tolerance / 2.0
    );
    worst
}

#[test]
fn box_corners_stay_within_half_the_tolerance_of_a_copy() {
    let child = Solid::cuboid(DVec3::new(1.0, 0.4, 0.3)).translate(DVec3::new(0.8, 0.0, 0.0));
    let path = bezier(&[
        [0.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [2.0, 2.0, 2.0],
        [-1.0, 2.0, 0.0],
    ]);
    for (frame, tolerance) in [
        (SweptFrame::Rmf, 0.15),
        (SweptFrame::Fixed, 0.15),
        (SweptFrame::Rmf, 0.02),
    ] {
        let worst = check_travel(&child, &path, frame, tolerance);
        // The spacing is not wasteful either: the worst corner uses most of the allowance.
        assert!(
            worst > 0.3 * tolerance,
            "{frame:?} {tolerance}: worst {worst}"
        );
    }
    let circle = Parametric::Curve(Curve::Nurbs(
        Nurbs::circle(DVec3::ZERO, 2.0).expect("circle"),
    ));
    check_travel(&child, &circle, SweptFrame::Rmf, 0.05);
}

#[test]
fn bounds_are_proven_unless_a_formula_derivative_is_unbounded() {
    let child = Solid::sphere(0.3);
    let helix = Parametric::Formula(
        crate::curve::FormulaCurve::new(["cos(u)", "sin(u)", "0.2*u"], (0.0, 6.0))
            .expect("formula"),
    );
    let swept = swept_volume(&child, &helix, SweptFrame::Rmf, Some(0.05)).expect("swept");
    assert!(swept.proven);
    check_travel(&child, &helix, SweptFrame::Rmf, 0.05);
    // A quotient whose denominator stays away from 0: bounded; sqrt at 0 (its derivative is
    // unbounded there): estimated.
    let bell = Parametric::Formula(
        crate::curve::FormulaCurve::new(["u", "1/(u*u + 0.5)", "0"], (-1.0, 1.0)).expect("formula"),
    );
    assert!(
        swept_volume(&child, &bell, SweptFrame::Fixed, Some(0.05))
            .expect("swept")
            .proven
    );
    let root = Parametric::Formula(
        crate::curve::FormulaCurve::new(["u", "sqrt(u)", "0"], (0.0, 1.0)).expect("formula"),
    );
    assert!(
        !swept_volume(&child, &root, SweptFrame::Fixed, Some(0.05))
            .expect("swept")
            .proven
    );
    let path = bezier(&[[0.0, 0.0, 0.0], [1.0, 2.0, 0.0], [3.0, -1.0, 1.0]]);
    assert!(
        swept_volume(&child, &path, SweptFrame::Rmf, Some(0.05))
            .expect("swept")
            .proven
    );
    let circle = Parametric::Curve(Curve::Nurbs(
        Nurbs::circle(DVec3::ZERO, 2.0).expect("circle"),
    ));
    assert!(
        swept_volume(&child, &circle, SweptFrame::Rmf, Some(0.05))
            .expect("swept")
            .proven
    );
}
