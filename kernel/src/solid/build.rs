//! Builder methods: primitives, Booleans and transforms as `Solid` constructors.
//!
//! Constructors never fail; parameters are checked by [`Solid::validate`] (the front ends call it
//! and report the offending node). Transforms with invalid parameters are stored as given and
//! rejected by validation too.

use super::{NodeKind, Solid};
use crate::primitive::{Cone, Cuboid, Cylinder, HalfSpace, Primitive, Sphere, Torus};
use crate::transform::{Transform, TransformSpec};
use glam::{DAffine3, DVec3};

impl Solid {
    /// A primitive leaf.
    pub fn primitive(p: Primitive) -> Solid {
        Solid::from_parts(NodeKind::Primitive(p), Vec::new())
    }

    /// A ball of radius `radius` centred at the origin.
    pub fn sphere(radius: f64) -> Solid {
        Solid::primitive(Primitive::Sphere(Sphere { radius }))
    }

    /// An axis-aligned box with side lengths `size`, centred at the origin.
    pub fn cuboid(size: DVec3) -> Solid {
        Solid::primitive(Primitive::Cuboid(Cuboid { size }))
    }

    /// A cube with side `side`, centred at the origin.
    pub fn cube(side: f64) -> Solid {
        Solid::cuboid(DVec3::splat(side))
    }

    /// A cylinder along z of radius `radius` and height `height`, centred at the origin.
    pub fn cylinder(radius: f64, height: f64) -> Solid {
        Solid::primitive(Primitive::Cylinder(Cylinder { radius, height }))
    }

    /// A capped cone along z, centred at the origin, radius `bottom` at `z = −h/2`, `top` at `+h/2`.
    pub fn cone(bottom: f64, top: f64, height: f64) -> Solid {
        Solid::primitive(Primitive::Cone(Cone {
            bottom_radius: bottom,
            top_radius: top,
            height,
        }))
    }

    /// A torus around the z axis.
    pub fn torus(major_radius: f64, minor_radius: f64) -> Solid {
        Solid::primitive(Primitive::Torus(Torus {
            major_radius,
            minor_radius,
        }))
    }

    /// The half-space `n̂ · p ≤ offset` (`n̂` the unit normal).
    pub fn half_space(normal: DVec3, offset: f64) -> Solid {
        Solid::primitive(Primitive::HalfSpace(HalfSpace { normal, offset }))
    }

    /// Union of any number of solids.
    pub fn union_all(solids: impl IntoIterator<Item = Solid>) -> Solid {
        Solid::from_parts(NodeKind::Union, solids.into_iter().collect())
    }

    /// Intersection of any number of solids.
    pub fn intersection_all(solids: impl IntoIterator<Item = Solid>) -> Solid {
        Solid::from_parts(NodeKind::Intersection, solids.into_iter().collect())
    }

    /// The first solid minus all the others.
    pub fn difference_all(base: Solid, cutters: impl IntoIterator<Item = Solid>) -> Solid {
        let mut children = vec![base];
        children.extend(cutters);
        Solid::from_parts(NodeKind::Difference, children)
    }

    /// `self ∪ other`.
    pub fn union(&self, other: &Solid) -> Solid {
        Solid::union_all([self.clone(), other.clone()])
    }

    /// `self ∩ other`.
    pub fn intersection(&self, other: &Solid) -> Solid {
        Solid::intersection_all([self.clone(), other.clone()])
    }

    /// `self ∖ other`.
    pub fn difference(&self, other: &Solid) -> Solid {
        Solid::difference_all(self.clone(), [other.clone()])
    }

    /// The solid under a transform given by its specification.
    pub fn transformed(&self, spec: TransformSpec) -> Solid {
        // An invalid spec is kept with an identity map; `validate` reports it.
        let t = Transform::new(spec).unwrap_or(Transform {
            spec,
            forward: DAffine3::IDENTITY,
            inverse: DAffine3::IDENTITY,
            sigma: f64::NAN,
        });
        Solid::from_parts(NodeKind::Transform(Box::new(t)), vec![self.clone()])
    }

    /// Moved by `offset`.
    pub fn translate(&self, offset: DVec3) -> Solid {
        self.transformed(TransformSpec::Translate(offset))
    }

    /// Rotated about `axis` (through the origin) by `degrees`.
    pub fn rotate(&self, axis: DVec3, degrees: f64) -> Solid {
        self.transformed(TransformSpec::Rotate { axis, degrees })
    }

    /// Scaled by per-axis `factors` (the field stays a distance bound).
    pub fn scale(&self, factors: DVec3) -> Solid {
        self.transformed(TransformSpec::Scale(factors))
    }

    /// Scaled uniformly by `factor`.
    pub fn scale_uniform(&self, factor: f64) -> Solid {
        self.scale(DVec3::splat(factor))
    }

    /// Reflected in the plane through the origin with normal `normal`.
    pub fn mirror(&self, normal: DVec3) -> Solid {
        self.transformed(TransformSpec::Mirror(normal))
    }

    /// Transformed by a general affine map `[A | t]` given row-major as 3 × 4.
    pub fn affine(&self, rows: [[f64; 4]; 3]) -> Solid {
        self.transformed(TransformSpec::Affine(rows))
    }

    /// The solid painted `color` (geometry unchanged; an inner colour wins over this one).
    pub fn color(&self, color: crate::color::Rgba) -> Solid {
        Solid::from_parts(NodeKind::Color(color), vec![self.clone()])
    }
}

impl Solid {
    /// Union of `solids` blended with fillets of `radius`.
    pub fn smooth_union_all(solids: impl IntoIterator<Item = Solid>, radius: f64) -> Solid {
        Solid::from_parts(
            NodeKind::SmoothUnion { radius },
            solids.into_iter().collect(),
        )
    }

    /// Intersection of `solids` with creases rounded by `radius`.
    pub fn smooth_intersection_all(solids: impl IntoIterator<Item = Solid>, radius: f64) -> Solid {
        Solid::from_parts(
            NodeKind::SmoothIntersection { radius },
            solids.into_iter().collect(),
        )
    }

    /// `base` minus `cutters` with creases rounded by `radius`.
    pub fn smooth_difference_all(
        base: Solid,
        cutters: impl IntoIterator<Item = Solid>,
        radius: f64,
    ) -> Solid {
        let mut children = vec![base];
        children.extend(cutters);
        Solid::from_parts(NodeKind::SmoothDifference { radius }, children)
    }

    /// `self ∪ other` with a fillet of `radius`.
    pub fn smooth_union(&self, other: &Solid, radius: f64) -> Solid {
        Solid::smooth_union_all([self.clone(), other.clone()], radius)
    }

    /// Grown by `distance` (shrunk when negative).
    pub fn offset(&self, distance: f64) -> Solid {
        Solid::from_parts(NodeKind::Offset { distance }, vec![self.clone()])
    }

    /// Hollowed to a wall of `thickness` centred on the surface.
    pub fn shell(&self, thickness: f64) -> Solid {
        Solid::from_parts(NodeKind::Shell { thickness }, vec![self.clone()])
    }
}

impl std::ops::BitOr for &Solid {
    type Output = Solid;
    fn bitor(self, rhs: &Solid) -> Solid {
        self.union(rhs)
    }
}

impl std::ops::BitAnd for &Solid {
    type Output = Solid;
    fn bitand(self, rhs: &Solid) -> Solid {
        self.intersection(rhs)
    }
}

impl std::ops::Sub for &Solid {
    type Output = Solid;
    fn sub(self, rhs: &Solid) -> Solid {
        self.difference(rhs)
    }
}
