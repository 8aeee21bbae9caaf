//! The conformance suite run for [`Program`] over the standard solids, and the adapter to
//! [`crate::Field`].

use super::conformance::{Checked, check_solids};
use super::{AsField, Evaluator, Pruned};
use crate::{Aabb, Field, Program, Solid};
use glam::DVec3;

#[test]
fn programs_conform() {
    let counts = check_solids(|s| s.compile());
    let mut total = Checked::default();
    for (name, c) in &counts {
        assert!(c.points > 5000 && c.boxes > 300, "{name}: {c:?}");
        assert!(
            c.gradients > c.points / 2,
            "{name}: few smooth points, {c:?}"
        );
        assert!(c.zeros > 0, "{name}: no zeros found, {c:?}");
        total.add(c);
    }
    // Every part of the contract was exercised somewhere: pruning (all but the sphere prune),
    // culled boxes, and zeros settled by the symbolic rule (the flush cutters).
    assert!(total.pruned > 100, "{total:?} {counts:?}");
    assert!(total.classified > 100, "{total:?}");
    assert!(total.settled_zeros > 10, "{total:?}");
    let flush = &counts
        .iter()
        .find(|(n, _)| *n == "box difference")
        .expect("listed")
        .1;
    assert!(flush.settled_zeros > 0, "{flush:?}");
}

#[test]
fn generic_calls_match_the_program_methods() {
    let p = Solid::sphere(0.5)
        .difference(&Solid::cylinder(0.2, 2.0))
        .compile();
    let b = Aabb::new(DVec3::new(0.45, -0.05, -0.05), DVec3::new(0.55, 0.05, 0.05));
    let generic = |e: &Program| match Evaluator::prune_for_box(e, &b, &mut Default::default()) {
        Pruned::Surface(Some(q)) => q.len(),
        other => panic!("{other:?}"),
    };
    let direct = match p.prune_for_box(&b, &mut Default::default()) {
        Pruned::Surface(Some(q)) => q.len(),
        other => panic!("{other:?}"),
    };
    assert_eq!(generic(&p), direct);
    assert!(direct < p.len());
    assert_eq!(Evaluator::len(&p), p.len());
}

#[test]
fn as_field_is_the_program_field() {
    let p = Solid::cube(1.0)
        .union(&Solid::cube(1.0).translate(DVec3::X))
        .compile();
    let f = AsField(&p);
    let pts = [
        DVec3::new(0.5, 0.0, 0.0),
        DVec3::new(0.2, 0.3, 0.1),
        DVec3::splat(2.0),
    ];
    let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
    f.values(&pts, &mut a);
    Field::values(&p, &pts, &mut b);
    assert_eq!(a, b);
    for q in pts {
        assert_eq!(f.value(q), Field::value(&p, q));
        assert_eq!(f.zero_side(q), Field::zero_side(&p, q));
    }
    // The shared face inside the union is settled inside, not left to the lattice.
    assert_eq!(f.zero_side(pts[0]), super::ZeroSide::Inside);
}

/// A fault planted in a program to show the suite catches it.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Fault {
    /// Batch values off by a relative 10⁻³.
    Batch,
    /// Batch values depend on the batch (the first point of every batch is one ulp off).
    Batching,
    /// Intervals a third too narrow about their middle.
    Interval,
    /// Pruning returns the pruned program of another box.
    Pruning,
    /// Gradients scaled by 1.01.
    Gradient,
    /// Zeros settled inside everywhere.
    ZeroSide,
}

/// A program with a fault.
#[derive(Clone)]
struct Faulty(Program, Fault);

impl Evaluator for Faulty {
    type BatchScratch = <Program as Evaluator>::BatchScratch;
    type PointScratch = <Program as Evaluator>::PointScratch;
    type GradientScratch = <Program as Evaluator>::GradientScratch;
    type IntervalScratch = <Program as Evaluator>::IntervalScratch;
    type ZeroScratch = <Program as Evaluator>::ZeroScratch;

    fn len(&self) -> usize {
        self.0.len()
    }

    fn eval_many(
        &self,
        x: &[f32],
        y: &[f32],
        z: &[f32],
        out: &mut [f32],
        s: &mut Self::BatchScratch,
    ) {
        self.0.eval_many(x, y, z, out, s);
        match self.1 {
            Fault::Batch => out.iter_mut().for_each(|v| *v *= 1.001),
            Fault::Batching if !out.is_empty() => out[0] = f32::from_bits(out[0].to_bits() ^ 1),
            _ => {}
        }
    }

    fn value_with(&self, p: DVec3, s: &mut Self::PointScratch) -> f64 {
        self.0.value_with(p, s)
    }

    fn values_gradients(
        &self,
        points: &[DVec3],
        values: &mut [f64],
        gradients: &mut [DVec3],
        s: &mut Self::GradientScratch,
    ) {
        self.0.values_gradients(points, values, gradients, s);
        if self.1 == Fault::Gradient {
            gradients.iter_mut().for_each(|g| *g *= 1.01);
        }
    }

    fn interval_with(&self, b: &Aabb, s: &mut Self::IntervalScratch) -> crate::Interval {
        let iv = self.0.interval_with(b, s);
        if self.1 == Fault::Interval && iv.lo.is_finite() && iv.hi.is_finite() {
            let (m, r) = (0.5 * (iv.lo + iv.hi), 0.5 * (iv.hi - iv.lo));
            return crate::Interval::new(m - r / 3.0, m + r / 3.0);
        }
        iv
    }

    fn prune(&self, s: &mut Self::IntervalScratch) -> Option<Self> {
        let p = if self.1 == Fault::Pruning {
            // Around the hole's wall, where only the hole counts.
            let far = Aabb::new(
                DVec3::new(-0.22, -0.02, -0.02),
                DVec3::new(-0.18, 0.02, 0.02),
            );
            match self.0.prune_for_box(&far, &mut Default::default()) {
                Pruned::Surface(Some(q)) => Some(q),
                other => panic!("{other:?}"),
            }
        } else {
            self.0.prune(s)
        };
        p.map(|q| Faulty(q, self.1))
    }

    fn zero_side(&self, p: DVec3, s: &mut Self::ZeroScratch) -> super::ZeroSide {
        match self.1 {
            Fault::ZeroSide => super::ZeroSide::Inside,
            _ => self.0.zero_side(p, s),
        }
    }
}

#[test]
fn the_suite_catches_faults() {
    use super::conformance::check_evaluator;
    let solid = Solid::difference_all(
        Solid::cube(1.0),
        [
            Solid::cube(0.5).translate(DVec3::splat(0.25)),
            Solid::cylinder(0.2, 1.0),
        ],
    );
    let region = Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
    // The sound program passes.
    check_evaluator(&Faulty(solid.compile(), Fault::Gradient).0, &region);
    for fault in [
        Fault::Batch,
        Fault::Batching,
        Fault::Interval,
        Fault::Pruning,
        Fault::Gradient,
        Fault::ZeroSide,
    ] {
        let e = Faulty(solid.compile(), fault);
        let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            check_evaluator(&e, &region)
        }));
        assert!(caught.is_err(), "{fault:?} went unnoticed");
    }
}
