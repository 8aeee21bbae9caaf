//! Axis-aligned bounding boxes: the bounds of solids, meshing domains and octree cells.

use glam::{DAffine3, DVec3};

/// An axis-aligned box `[min, max]`. A box with any `min > max` component is empty; components
/// may be infinite for unbounded solids (a half-space).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Minimum corner.
    pub min: DVec3,
    /// Maximum corner.
    pub max: DVec3,
}

impl Aabb {
    /// The box with corners `min` and `max`.
    pub fn new(min: DVec3, max: DVec3) -> Self {
        Self { min, max }
    }

    /// The box containing nothing.
    pub fn empty() -> Self {
        Self {
            min: DVec3::splat(f64::INFINITY),
            max: DVec3::splat(f64::NEG_INFINITY),
        }
    }

    /// The box containing everything.
    pub fn infinite() -> Self {
        Self {
            min: DVec3::splat(f64::NEG_INFINITY),
            max: DVec3::splat(f64::INFINITY),
        }
    }

    /// The cube `[-h, h]³`-style box centred at the origin with half extents `half`.
    pub fn centered(half: DVec3) -> Self {
        Self {
            min: -half,
            max: half,
        }
    }

    /// True when the box contains no point.
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// True when every bound is finite and the box is not empty.
    pub fn is_finite(&self) -> bool {
        !self.is_empty() && self.min.is_finite() && self.max.is_finite()
    }

    /// Smallest box containing both.
    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    /// Intersection of both (possibly empty).
    pub fn intersection(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(o.min),
            max: self.max.min(o.max),
        }
    }

    /// Centre point (finite boxes only).
    pub fn center(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    /// Half extents (finite boxes only).
    pub fn half_extents(&self) -> DVec3 {
        (self.max - self.min) * 0.5
    }

    /// Extents `max - min`.
    pub fn size(&self) -> DVec3 {
        self.max - self.min
    }

    /// True when `p` is inside or on the boundary.
    pub fn contains(&self, p: DVec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// The box grown by `d` on every side.
    pub fn expanded(&self, d: f64) -> Aabb {
        Aabb {
            min: self.min - DVec3::splat(d),
            max: self.max + DVec3::splat(d),
        }
    }

    /// Bounding box of the image of this box under an affine map. Infinite boxes map to boxes
    /// that are infinite along every axis an infinite extent can reach.
    pub fn transformed(&self, m: &DAffine3) -> Aabb {
        if self.is_empty() {
            return *self;
        }
        if self.is_finite() {
            let c = m.transform_point3(self.center());
            let h = self.half_extents();
            let a = m.matrix3;
            let r = a.x_axis.abs() * h.x + a.y_axis.abs() * h.y + a.z_axis.abs() * h.z;
            return Aabb {
                min: c - r,
                max: c + r,
            };
        }
        transformed_unbounded(self, m)
    }
}

/// Image of a box with infinite bounds: finite parts map as usual, every axis that receives a
/// contribution from an infinite extent becomes infinite.
fn transformed_unbounded(b: &Aabb, m: &DAffine3) -> Aabb {
    let cols = [m.matrix3.x_axis, m.matrix3.y_axis, m.matrix3.z_axis];
    let mut min = m.translation;
    let mut max = m.translation;
    for (axis, col) in cols.iter().enumerate() {
        let (lo, hi) = (b.min[axis], b.max[axis]);
        for out in 0..3 {
            let k = col[out];
            if k == 0.0 {
                continue;
            }
            let (a, c) = (lo * k, hi * k);
            min[out] += a.min(c);
            max[out] += a.max(c);
        }
    }
    Aabb { min, max }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    #[test]
    fn rotated_box_contains_rotated_corners() {
        let b = Aabb::new(DVec3::new(-1.0, 0.0, 2.0), DVec3::new(1.0, 3.0, 2.5));
        let m = DAffine3::from_rotation_translation(
            DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7),
            DVec3::new(0.5, -1.0, 4.0),
        );
        let t = b.transformed(&m);
        for i in 0..8 {
            let p = DVec3::new(
                if i & 1 == 0 { b.min.x } else { b.max.x },
                if i & 2 == 0 { b.min.y } else { b.max.y },
                if i & 4 == 0 { b.min.z } else { b.max.z },
            );
            let q = m.transform_point3(p);
            assert!(t.expanded(1e-12).contains(q), "{q} not in {t:?}");
        }
    }

    #[test]
    fn half_space_box_stays_unbounded_where_it_should() {
        let b = Aabb::new(
            DVec3::new(f64::NEG_INFINITY, -1.0, -1.0),
            DVec3::new(0.0, 1.0, 1.0),
        );
        let t = b.transformed(&DAffine3::from_translation(DVec3::X));
        assert_eq!(t.max.x, 1.0);
        assert_eq!(t.min.x, f64::NEG_INFINITY);
        assert_eq!(t.min.y, -1.0);
        assert!(Aabb::empty().is_empty() && !Aabb::infinite().is_finite());
    }
}
