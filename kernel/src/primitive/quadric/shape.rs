//! The quadric primitive: a [`QuadricForm`] (general coefficients or a named quadric), its
//! classification, and the solid `{Q ≤ 0}` bounded by a box where it is unbounded, evaluated by the
//! 2-Lipschitz bounded field described in the [module docs](super).

use super::classify::{Classification, QuadricKind, classify};
use super::coefficients::QuadricCoefficients;
use super::field::BoundedField;
use super::form::QuadricForm;
use crate::primitive::{PrimitiveError, Shape};
use crate::{Aabb, Interval};
use glam::DVec3;

/// The solid `{Q ≤ 0} ∩ bounds` of a quadric. Build it with [`Quadric::new`]; the bounding box is
/// required unless `A` is positive definite (then the solid is an ellipsoid, whose own box is used).
#[derive(Debug, Clone, PartialEq)]
pub struct Quadric {
    form: QuadricForm,
    bounds: Option<Aabb>,
    classification: Classification,
    field: BoundedField,
}

fn error(parameter: &'static str, problem: &'static str) -> PrimitiveError {
    PrimitiveError { parameter, problem }
}

impl Quadric {
    /// The solid `{Q ≤ 0}` of `form`, intersected with `bounds` when given. Fails when a parameter
    /// is invalid, when `bounds` is missing for an unbounded solid, or when the solid is empty
    /// because `A` is positive definite and `Q > 0` everywhere (or the box misses the ellipsoid).
    pub fn new(form: QuadricForm, bounds: Option<Aabb>) -> Result<Self, PrimitiveError> {
        form.validate()?;
        if let Some(b) = bounds {
            let ok = b.is_finite() && b.min.cmplt(b.max).all();
            if !ok {
                return Err(error("bounds", "expected a finite box with min below max"));
            }
        }
        let coefficients = form.coefficients();
        let classification = classify(&coefficients);
        let natural = ellipsoid_box(&coefficients, classification.eigenvalues);
        let boxed = match (bounds, natural) {
            (Some(b), Some(Some(n))) => b.intersection(&n),
            (Some(b), None) => b,
            (None, Some(Some(n))) => n,
            (_, Some(None)) => {
                return Err(error("coefficients", "the solid Q ≤ 0 is empty"));
            }
            (None, None) => {
                return Err(error("bounds", "required for an unbounded quadric"));
            }
        };
        if !boxed.min.cmplt(boxed.max).all() {
            return Err(error("bounds", "the box does not meet the solid"));
        }
        let sigma = classification.eigenvalues.abs().max_element();
        let field = BoundedField::new(coefficients, boxed, sigma)
            .ok_or_else(|| error("coefficients", "Q is constant over the bounds"))?;
        Ok(Self {
            form,
            bounds,
            classification,
            field,
        })
    }

    /// The general quadric with these coefficients.
    pub fn general(
        coefficients: QuadricCoefficients,
        bounds: Option<Aabb>,
    ) -> Result<Self, PrimitiveError> {
        Self::new(QuadricForm::General(coefficients), bounds)
    }

    /// How the quadric was given.
    pub fn form(&self) -> &QuadricForm {
        &self.form
    }

    /// The bounding box as given (`None` for an ellipsoid given without one).
    pub fn bounds(&self) -> Option<Aabb> {
        self.bounds
    }

    /// The coefficients of `Q`.
    pub fn coefficients(&self) -> QuadricCoefficients {
        self.form.coefficients()
    }

    /// The surface type and the invariants it was read from.
    pub fn classification(&self) -> &Classification {
        &self.classification
    }

    /// The surface type.
    pub fn kind(&self) -> QuadricKind {
        self.classification.kind
    }

    /// The node type in the JSON tree format.
    pub fn name(&self) -> &'static str {
        self.form.name()
    }
}

/// When `A` is positive definite: `Some(box)` of the ellipsoid `(x − c)ᵀA(x − c) ≤ k`
/// (`c = −A⁻¹l`, `k = lᵀA⁻¹l − d`, half extents `√(k (A⁻¹)_ii)`), or `Some(None)` when `k ≤ 0` (the
/// solid is empty or a point). `None` when `A` is not positive definite (unbounded solid).
fn ellipsoid_box(q: &QuadricCoefficients, eigenvalues: DVec3) -> Option<Option<Aabb>> {
    let max = eigenvalues.abs().max_element();
    let definite = eigenvalues.min_element() > 1e-10 * max;
    if !definite {
        return None;
    }
    let inv = q.matrix3().inverse();
    let center = -(inv * q.linear());
    let k = -q.linear().dot(center) - q.d;
    if k.is_nan() || k <= 0.0 {
        return Some(None);
    }
    let half = DVec3::new(inv.x_axis.x, inv.y_axis.y, inv.z_axis.z).max(DVec3::ZERO) * k;
    let half = half.map(f64::sqrt) * (1.0 + 1e-9)
        + DVec3::splat(1e-12 * (1.0 + center.abs().max_element()));
    Some(Some(Aabb::new(center - half, center + half)))
}

impl Shape for Quadric {
    fn value(&self, p: DVec3) -> f64 {
        self.field.value(p)
    }
    fn gradient(&self, p: DVec3) -> DVec3 {
        self.field.gradient(p)
    }
    fn interval(&self, b: &Aabb) -> Interval {
        self.field.interval(b)
    }
    fn bbox(&self) -> Aabb {
        self.field.bounds()
    }
    fn validate(&self) -> Result<(), PrimitiveError> {
        self.form.validate()
    }
    fn lipschitz(&self) -> f64 {
        self.field.lipschitz()
    }
}
