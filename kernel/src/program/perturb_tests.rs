//! Tests of the symbolic inside test at zeros: shared faces inside unions are inside, flush
//! cutters' faces are outside, creases and corners take the exact one-sided sign, the direction
//! is generic for lattice models, and a pruned program settles every zero as the full one does.

use super::perturb::{PERTURBATION, ZeroSide};
use super::{IntervalScratch, Pruned};
use crate::primitive::conformance::Rng;
use crate::{Aabb, Solid};
use glam::DVec3;

fn unit_box_at(x: f64, y: f64, z: f64) -> Solid {
    Solid::cuboid(DVec3::ONE).translate(DVec3::new(x, y, z) + DVec3::splat(0.5))
}

fn side(s: &Solid, p: DVec3) -> ZeroSide {
    s.compile().zero_side(p, &mut Vec::new())
}

fn inside(s: &Solid, p: DVec3) -> bool {
    side(s, p) == ZeroSide::Inside
}

#[test]
fn perturbation_is_a_generic_unit_direction() {
    assert!((PERTURBATION.length() - 1.0).abs() < 1e-15);
    // No plane with a small-integer normal contains it: never tangent to a lattice face.
    for a in -4i32..=4 {
        for b in -4i32..=4 {
            for c in -4i32..=4 {
                if (a, b, c) != (0, 0, 0) {
                    let n = DVec3::new(a as f64, b as f64, c as f64).normalize();
                    assert!(n.dot(PERTURBATION).abs() > 1e-2, "{a} {b} {c}");
                }
            }
        }
    }
}

#[test]
fn shared_face_of_a_union_is_inside() {
    let u = unit_box_at(0.0, 0.0, 0.0).union(&unit_box_at(1.0, 0.0, 0.0));
    let p = DVec3::new(1.0, 0.5, 0.5);
    assert_eq!(u.compile().value(p), 0.0);
    assert!(inside(&u, p));
    // The outer faces touch no other operand: outside.
    assert!(!inside(&u, DVec3::new(0.0, 0.5, 0.5)));
    assert!(!inside(&u, DVec3::new(2.0, 0.5, 0.5)));
    // An edge shared by four boxes of a stack, and a corner shared by eight.
    let stack = Solid::union_all(
        (0..8).map(|i| unit_box_at((i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64)),
    );
    assert!(inside(&stack, DVec3::new(1.0, 1.0, 0.5)));
    assert!(inside(&stack, DVec3::ONE));
}

#[test]
fn flush_cutter_face_is_outside() {
    let plate = Solid::cuboid(DVec3::new(4.0, 4.0, 1.0)).translate(DVec3::new(0.0, 0.0, 0.5));
    let cutter = Solid::cylinder(0.5, 1.0).translate(DVec3::new(0.0, 0.0, 0.5));
    let holed = plate.difference(&cutter);
    for z in [0.0, 1.0] {
        let p = DVec3::new(0.1, -0.2, z);
        assert_eq!(holed.compile().value(p), 0.0);
        assert!(!inside(&holed, p), "skin over the hole at z = {z}");
    }
    // The same cutter flush with a face from outside leaves the face where it was.
    let touching = plate.difference(&cutter.translate(DVec3::Z));
    assert!(!inside(&touching, DVec3::new(0.1, 0.1, 0.0)));
    assert!(!inside(&touching, DVec3::new(0.1, 0.1, 1.0)));
}

#[test]
fn zeros_on_a_lone_surface_are_left_to_the_lattice() {
    // No other operand touches a box's corners, edges or faces, nor a sphere: the polygonizer
    // decides (the step rule applies to contacts only; at a sharp tip it would leave an inside
    // island).
    let b = unit_box_at(0.0, 0.0, 0.0);
    for p in [
        DVec3::ZERO,
        DVec3::X,
        DVec3::ONE,
        DVec3::new(0.5, 0.0, 0.0),
        DVec3::new(0.5, 0.5, 0.0),
    ] {
        assert_eq!(side(&b, p), ZeroSide::Surface, "{p}");
    }
    let d = PERTURBATION;
    let s = Solid::sphere(1.0);
    assert_eq!(side(&s, -d), ZeroSide::Surface);
    assert_eq!(
        side(&s, DVec3::new(-d.y, d.x, 0.0).normalize()),
        ZeroSide::Surface
    );
    // Off the surface the value decides.
    assert_eq!(side(&s, DVec3::ZERO), ZeroSide::Inside);
}

#[test]
fn pruned_programs_settle_zeros_as_the_full_program() {
    // Random unions and differences of lattice boxes, every lattice point, pruned for every
    // lattice cell around it.
    let mut rng = Rng::new(7);
    let mut zeros = 0;
    for _ in 0..20 {
        let mut s = unit_box_at(0.0, 0.0, 0.0);
        for _ in 0..6 {
            let p = [0, 1, 2].map(|_| (rng.next() * 3.0).floor() - 1.0);
            let size = DVec3::new(1.0 + (rng.next() * 2.0).floor(), 1.0, 1.0);
            let b = Solid::cuboid(size).translate(DVec3::new(p[0], p[1], p[2]) + size * 0.5);
            s = if rng.next() < 0.6 {
                s.union(&b)
            } else {
                s.difference(&b)
            };
        }
        let full = s.compile();
        let mut scratch = IntervalScratch::default();
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for cell in 0..64 {
            let lo = DVec3::new(
                (cell & 3) as f64,
                (cell >> 2 & 3) as f64,
                (cell >> 4) as f64,
            ) - DVec3::splat(1.5);
            let bx = Aabb::new(lo, lo + DVec3::splat(0.5));
            let Pruned::Surface(Some(pruned)) = full.prune_for_box(&bx, &mut scratch) else {
                continue;
            };
            for corner in 0..8 {
                let p = lo
                    + DVec3::new(
                        (corner & 1) as f64,
                        (corner >> 1 & 1) as f64,
                        (corner >> 2) as f64,
                    ) * 0.5;
                if full.value(p) == 0.0 {
                    zeros += 1;
                    assert_eq!(
                        full.zero_side(p, &mut a),
                        pruned.zero_side(p, &mut b),
                        "{p}"
                    );
                }
            }
        }
    }
    assert!(zeros > 100, "{zeros}");
}

#[test]
fn point_and_line_contacts_stay_apart() {
    // Two balls touching at the origin: the pinch is outside (two solids), though the step along
    // the perturbation lands in one of them.
    let balls = Solid::sphere(0.5)
        .translate(DVec3::new(-0.5, 0.0, 0.0))
        .union(&Solid::sphere(0.5).translate(DVec3::new(0.5, 0.0, 0.0)));
    assert_eq!(balls.compile().value(DVec3::ZERO), 0.0);
    assert!(!inside(&balls, DVec3::ZERO));
    // Two cylinders side by side touching along the z axis.
    let rods = Solid::cylinder(0.5, 2.0)
        .translate(DVec3::new(-0.5, 0.0, 0.0))
        .union(&Solid::cylinder(0.5, 2.0).translate(DVec3::new(0.5, 0.0, 0.0)));
    assert!(!inside(&rods, DVec3::new(0.0, 0.0, 0.25)));
    // Two ball cavities touching inside a block: the material between them is kept.
    let block = Solid::cuboid(DVec3::splat(4.0)).difference(&balls.clone());
    assert!(inside(&block, DVec3::ZERO));
    // A shared face is still inside, also next to its rim.
    let u = unit_box_at(0.0, 0.0, 0.0).union(&unit_box_at(1.0, 0.0, 0.0));
    assert!(inside(&u, DVec3::new(1.0, 0.001, 0.999)));
}

#[test]
fn edge_contacts_stay_apart() {
    // Two unit cubes sharing only the edge x = y = 1: a sample on the edge is outside.
    let cubes = unit_box_at(0.0, 0.0, 0.0).union(&unit_box_at(1.0, 1.0, 0.0));
    let p = DVec3::new(1.0, 1.0, 0.5);
    assert_eq!(cubes.compile().value(p), 0.0);
    assert!(!inside(&cubes, p));
    // Two cubes sharing a face and a third touching one of them along an edge: the face stays
    // inside, the edge outside.
    let three = cubes.union(&unit_box_at(1.0, 0.0, 0.0).translate(DVec3::new(0.0, 0.0, 2.0)));
    assert!(!inside(&three, p));
    let faces = unit_box_at(0.0, 0.0, 0.0).union(&unit_box_at(1.0, 0.0, 0.0));
    assert!(inside(&faces, DVec3::new(1.0, 0.5, 0.5)));
}
