//! Conformance checks every primitive must pass: the field respects its Lipschitz bound, the
//! single-precision batch path agrees with the scalar one, the gradient agrees with finite
//! differences, intervals contain every sampled value, and the bounding box contains every sampled
//! inside point. New primitives call [`check_shape`] from their tests.

use super::*;

/// Deterministic pseudo-random numbers in `[-1, 1)` (xorshift), so failures reproduce.
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    pub(crate) fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    pub(crate) fn vec(&mut self, scale: f64) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next()) * scale
    }
}

pub(crate) fn check_shape(shape: &impl Shape, extent: f64) {
    shape.validate().expect("valid parameters");
    let mut rng = Rng::new(7);
    let bbox = shape.bbox();
    for _ in 0..2000 {
        let a = rng.vec(extent);
        let b = a + rng.vec(extent * 0.1);
        let (fa, fb) = (shape.value(a), shape.value(b));
        let lip = shape.lipschitz();
        assert!(
            (fa - fb).abs() <= lip * (a - b).length() * (1.0 + 1e-9) + 1e-12,
            "not {lip}-Lipschitz at {a}"
        );
        // The single-precision batch path agrees with the scalar one.
        let mut out = [0f32; 1];
        shape.values_f32(&[a.x as f32], &[a.y as f32], &[a.z as f32], &mut out);
        let tol = 1e-5 * (1.0 + fa.abs() + extent * lip);
        assert!(
            (out[0] as f64 - fa).abs() <= tol,
            "values_f32 {} vs value {fa} at {a}",
            out[0]
        );
        // The double-precision batch path gives the scalar values and gradients bit for bit.
        let (mut v, mut g) = ([0.0; 2], [DVec3::ZERO; 2]);
        shape.values_gradients(&[a, b], &mut v, &mut g);
        assert_eq!(
            v[0].to_bits(),
            fa.to_bits(),
            "values_gradients value at {a}"
        );
        assert_eq!(
            v[1].to_bits(),
            fb.to_bits(),
            "values_gradients value at {b}"
        );
        let ga = shape.gradient(a);
        assert!(
            g[0].to_array()
                .iter()
                .zip(ga.to_array())
                .all(|(x, y)| x.to_bits() == y.to_bits()),
            "values_gradients gradient {} vs {ga} at {a}",
            g[0]
        );
        if fa < 0.0 {
            assert!(
                bbox.expanded(1e-9).contains(a),
                "inside point {a} outside bbox"
            );
        }
        // The sublevel boxes offsets and shells use hold their sublevel sets (issue 15).
        for level in [0.02, 0.2, 1.0].map(|k| k * extent) {
            if fa <= level && shape.sublevel_boxes_hold() {
                assert!(
                    shape.bbox_at(level).expanded(1e-9 * extent).contains(a),
                    "point {a} with value {fa} <= {level} outside bbox_at({level})"
                );
            }
        }
        // Gradient against central differences, away from creases where it is discontinuous.
        let h = 1e-6 * extent;
        let fd = DVec3::new(
            shape.value(a + DVec3::X * h) - shape.value(a - DVec3::X * h),
            shape.value(a + DVec3::Y * h) - shape.value(a - DVec3::Y * h),
            shape.value(a + DVec3::Z * h) - shape.value(a - DVec3::Z * h),
        ) / (2.0 * h);
        let g = shape.gradient(a);
        // Skip creases: where a wider difference disagrees, the field is not smooth there.
        let h2 = 4.0 * h;
        let fd2 = DVec3::new(
            shape.value(a + DVec3::X * h2) - shape.value(a - DVec3::X * h2),
            shape.value(a + DVec3::Y * h2) - shape.value(a - DVec3::Y * h2),
            shape.value(a + DVec3::Z * h2) - shape.value(a - DVec3::Z * h2),
        ) / (2.0 * h2);
        let smooth = (fd - fd2).length() < 1e-5 * (1.0 + fd.length());
        if smooth {
            assert!(
                (g - fd).length() < 1e-3 * (1.0 + fd.length()),
                "gradient {g} vs finite difference {fd} at {a}"
            );
        }
        // Intervals over random boxes contain sampled values.
        let c = rng.vec(extent);
        let half = rng.vec(extent * 0.3).abs();
        let cell = Aabb::new(c - half, c + half);
        let iv = shape.interval(&cell);
        for k in 0..9 {
            let t = DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64);
            let t = if k == 8 { DVec3::splat(0.5) } else { t };
            let p = cell.min + (cell.max - cell.min) * t;
            let v = shape.value(p);
            assert!(
                iv.lo <= v + 1e-12 && v <= iv.hi + 1e-12,
                "{v} not in {iv:?} over {cell:?}"
            );
        }
    }
}

#[test]
fn sphere_conforms() {
    check_shape(&Sphere { radius: 0.7 }, 1.5);
}

#[test]
fn cuboid_conforms() {
    check_shape(
        &Cuboid {
            size: DVec3::new(1.0, 0.4, 1.6),
        },
        1.5,
    );
}

#[test]
fn cylinder_conforms() {
    check_shape(
        &Cylinder {
            radius: 0.5,
            height: 1.2,
        },
        1.5,
    );
}

#[test]
fn cone_conforms() {
    check_shape(
        &Cone {
            bottom_radius: 0.8,
            top_radius: 0.2,
            height: 1.0,
        },
        1.5,
    );
    check_shape(
        &Cone {
            bottom_radius: 0.0,
            top_radius: 0.6,
            height: 1.4,
        },
        1.5,
    );
}

#[test]
fn torus_conforms() {
    check_shape(
        &Torus {
            major_radius: 1.0,
            minor_radius: 0.3,
        },
        1.6,
    );
}

#[test]
fn half_space_conforms() {
    check_shape(
        &HalfSpace {
            normal: DVec3::new(1.0, -2.0, 0.5),
            offset: 0.3,
        },
        1.5,
    );
}

#[test]
fn cone_matches_cylinder_when_radii_agree() {
    let cone = Cone {
        bottom_radius: 0.5,
        top_radius: 0.5,
        height: 1.0,
    };
    let cyl = Cylinder {
        radius: 0.5,
        height: 1.0,
    };
    let mut rng = Rng::new(3);
    for _ in 0..1000 {
        let p = rng.vec(1.2);
        assert!((cone.value(p) - cyl.value(p)).abs() < 1e-12);
    }
}

#[test]
fn invalid_parameters_are_named() {
    let e = Sphere { radius: f64::NAN }.validate().unwrap_err();
    assert_eq!(e.parameter, "radius");
    let e = Sphere { radius: -1.0 }.validate().unwrap_err();
    assert_eq!(e.to_string(), "radius: expected a positive number");
    assert!(
        Cone {
            bottom_radius: 0.0,
            top_radius: 0.0,
            height: 1.0
        }
        .validate()
        .is_err()
    );
    assert!(
        Torus {
            major_radius: 1.0,
            minor_radius: 0.0
        }
        .validate()
        .is_err()
    );
}
