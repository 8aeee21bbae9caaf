//! The field evaluated through programs pruned to the cubes of a coarse lattice: a cube's pruned
//! program gives the same values, bit for bit, as the whole one inside the cube, and the checks
//! sample the field many times near few places.

use crate::io::key_hash::KeyHash;
use glam::DVec3;
use solidkit_kernel::{Aabb, Evaluator};
use std::cell::RefCell;
use std::collections::HashMap;

/// The field with a cache of pruned programs, one per cube of side `size`.
pub(crate) struct LocalField<'a, E: Evaluator> {
    field: &'a E,
    size: f64,
    cache: RefCell<HashMap<[i64; 3], Option<E>, KeyHash>>,
    interval: RefCell<E::IntervalScratch>,
    point: RefCell<E::PointScratch>,
    gradient: RefCell<E::GradientScratch>,
}

impl<'a, E: Evaluator> LocalField<'a, E> {
    /// `field` over cubes of side `size`.
    pub fn new(field: &'a E, size: f64) -> Self {
        Self {
            field,
            size,
            cache: RefCell::default(),
            interval: RefCell::default(),
            point: RefCell::default(),
            gradient: RefCell::default(),
        }
    }

    /// Runs `f` with the evaluator valid at `p` (the pruned one of its cube, or the whole field).
    fn with<R>(&self, p: DVec3, f: impl FnOnce(&E) -> R) -> R {
        let k = (p / self.size).floor();
        let key = [k.x as i64, k.y as i64, k.z as i64];
        let lo = DVec3::new(key[0] as f64, key[1] as f64, key[2] as f64) * self.size;
        let hi = lo + DVec3::splat(self.size);
        if !(p.is_finite() && lo.cmple(p).all() && p.cmple(hi).all()) {
            return f(self.field);
        }
        let mut cache = self.cache.borrow_mut();
        let local = cache.entry(key).or_insert_with(|| {
            let mut s = self.interval.borrow_mut();
            self.field.interval_with(&Aabb::new(lo, hi), &mut s);
            self.field.prune(&mut s)
        });
        f(local.as_ref().unwrap_or(self.field))
    }

    /// The value at `p`.
    pub fn value(&self, p: DVec3) -> f64 {
        self.with(p, |e| e.value_with(p, &mut self.point.borrow_mut()))
    }

    /// The gradient at `p`.
    pub fn gradient(&self, p: DVec3) -> DVec3 {
        self.with(p, |e| {
            let (mut v, mut g) = ([0.0], [DVec3::ZERO]);
            e.values_gradients(&[p], &mut v, &mut g, &mut self.gradient.borrow_mut());
            g[0]
        })
    }
}
