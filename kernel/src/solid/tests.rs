//! Tree-level tests: deep trees in every operation, equality, validation paths, bounding boxes.

use crate::{Aabb, KernelError, Solid, json};
use glam::DVec3;

/// Runs `f` on a thread with a deliberately small stack, so any recursion over a deep tree fails.
fn on_small_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(f)
        .expect("spawn")
        .join()
        .expect("no stack overflow");
}

/// A left-leaning chain `(((s0 ∪ s1) ∪ s2) ∪ …)` of `n` unions of small spheres along x.
fn chain(n: usize) -> Solid {
    let mut s = Solid::sphere(0.5);
    for i in 1..=n {
        s = s.union(&Solid::sphere(0.5).translate(DVec3::new(i as f64 * 1e-3, 0.0, 0.0)));
    }
    s
}

#[test]
fn hundred_thousand_deep_chain_survives_every_operation() {
    on_small_stack(|| {
        let n = 100_000;
        let s = chain(n);
        let copy = s.clone();
        assert_eq!(s.node_count(), 1 + 3 * n);
        assert_eq!(s.depth(), n + 2);
        assert!(s == copy);
        s.validate().unwrap();
        let b = s.bbox();
        assert!((b.max.x - (0.5 + n as f64 * 1e-3)).abs() < 1e-9);
        let tape = s.compile();
        assert!((tape.value(DVec3::new(-1.0, 0.0, 0.0)) - 0.5).abs() < 1e-12);
        assert!((tape.gradient(DVec3::new(-1.0, 0.0, 0.0)) + DVec3::X).length() < 1e-12);
        let iv = tape.interval(&Aabb::new(DVec3::splat(-0.1), DVec3::splat(0.1)));
        assert!(iv.hi < 0.0);
        let text = json::to_string(&s);
        let back = json::from_str(&text).unwrap();
        assert!(back == s);
        // A deep copy that shares nothing with `s`, dropped while `s` is still alive, then both.
        drop(back);
        drop(copy);
        drop(s);
    });
}

#[test]
fn deep_chain_of_transforms_and_differences() {
    on_small_stack(|| {
        let mut s = Solid::cube(1.0);
        for i in 0..50_000 {
            s = if i % 2 == 0 {
                s.translate(DVec3::new(1e-6, 0.0, 0.0))
            } else {
                s.difference(&Solid::sphere(0.01).translate(DVec3::new(5.0, 5.0, 5.0)))
            };
        }
        let v = s.compile().value(DVec3::ZERO);
        assert!((v + 0.5 - 0.025).abs() < 1e-3, "{v}");
        assert!(json::from_str(&json::to_string(&s)).unwrap() == s);
    });
}

#[test]
fn validation_names_the_offending_node() {
    let s = Solid::union_all([
        Solid::sphere(1.0),
        Solid::sphere(0.5)
            .translate(DVec3::X)
            .union(&Solid::torus(1.0, -0.2)),
    ]);
    let err = s.validate().unwrap_err();
    assert_eq!(
        err,
        KernelError::InvalidNode {
            path: "children[1].children[1]".into(),
            problem: "minor_radius: expected a positive number".into()
        }
    );
    let singular = Solid::sphere(1.0).scale(DVec3::new(1.0, 0.0, 1.0));
    assert!(
        singular
            .validate()
            .unwrap_err()
            .to_string()
            .contains("singular")
    );
    assert!(Solid::sphere(f64::NAN).validate().is_err());
}

#[test]
fn bounding_boxes_follow_the_operations() {
    let a = Solid::sphere(1.0);
    let b = Solid::cube(1.0).translate(DVec3::new(3.0, 0.0, 0.0));
    let u = a.union(&b).bbox();
    assert_eq!(u.min, DVec3::splat(-1.0));
    assert_eq!(u.max, DVec3::new(3.5, 1.0, 1.0));
    let i = a.intersection(&Solid::half_space(DVec3::Z, 0.25)).bbox();
    assert_eq!(i.max.z, 0.25);
    assert_eq!(a.difference(&b).bbox(), a.bbox());
    let r = Solid::cuboid(DVec3::new(2.0, 0.0 + 1.0, 1.0))
        .rotate(DVec3::Z, 90.0)
        .bbox();
    assert!((r.max - DVec3::new(0.5, 1.0, 0.5)).length() < 1e-12);
}

#[test]
fn operators_build_the_same_trees_as_methods() {
    let a = Solid::sphere(1.0);
    let b = Solid::cube(1.5);
    assert!(&a | &b == a.union(&b));
    assert!(&a & &b == a.intersection(&b));
    assert!(&a - &b == a.difference(&b));
    assert!(&a - &b != &b - &a);
}
