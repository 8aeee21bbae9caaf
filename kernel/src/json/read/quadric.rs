//! Reading the quadric family: `ellipsoid` (radii [a, b, c]); `quadric` (coefficients: an object
//! with any of the keys a, b, c, f, g, h, p, q, r, d, missing ones 0; optional bounds); the named
//! `elliptic_cylinder`, `elliptic_cone`, `elliptic_paraboloid`, `hyperbolic_paraboloid` (radii
//! [a, b]) and `hyperboloid_one_sheet`, `hyperboloid_two_sheets` (radii [a, b, c]), each with the
//! required `bounds`: [[min x, y, z], [max x, y, z]].

use super::super::document::Value;
use super::{Params, R};
use crate::Aabb;
use crate::primitive::quadric::{QuadricCoefficients, QuadricForm};
use crate::primitive::{Ellipsoid, Primitive, Quadric};
use glam::DVec3;
use std::sync::Arc;

const COEFFICIENT_KEYS: [&str; 10] = ["a", "b", "c", "f", "g", "h", "p", "q", "r", "d"];

impl Params<'_, '_> {
    /// The primitive of a quadric-family node type.
    pub(super) fn quadric_family(&self, ty: &str) -> R<(Primitive, &'static [&'static str])> {
        const NAMED: &[&str] = &["radii", "bounds"];
        let form = match ty {
            "ellipsoid" => {
                let e = Ellipsoid {
                    radii: self.vec3("radii")?,
                };
                return Ok((Primitive::Ellipsoid(e), &["radii"]));
            }
            "quadric" => QuadricForm::General(self.quadric_coefficients()?),
            "elliptic_cylinder" => QuadricForm::EllipticCylinder {
                radii: self.numbers::<2>(self.at("radii")?, "radii")?,
            },
            "elliptic_cone" => QuadricForm::EllipticCone {
                radii: self.numbers::<2>(self.at("radii")?, "radii")?,
            },
            "elliptic_paraboloid" => QuadricForm::EllipticParaboloid {
                radii: self.numbers::<2>(self.at("radii")?, "radii")?,
            },
            "hyperbolic_paraboloid" => QuadricForm::HyperbolicParaboloid {
                radii: self.numbers::<2>(self.at("radii")?, "radii")?,
            },
            "hyperboloid_one_sheet" => QuadricForm::HyperboloidOfOneSheet {
                radii: self.numbers::<3>(self.at("radii")?, "radii")?,
            },
            "hyperboloid_two_sheets" => QuadricForm::HyperboloidOfTwoSheets {
                radii: self.numbers::<3>(self.at("radii")?, "radii")?,
            },
            other => {
                let t = self.at("type")?;
                return Err(self.fail(t, "type", format!("unknown node type \"{other}\"")));
            }
        };
        let bounds = self.quadric_bounds("bounds")?;
        let quadric = Quadric::new(form, bounds).map_err(|e| {
            let at = self.at(e.parameter).unwrap_or(self.index);
            self.fail(at, e.parameter, e.problem)
        })?;
        let allowed: &'static [&'static str] = match form {
            QuadricForm::General(_) => &["coefficients", "bounds"],
            _ => NAMED,
        };
        Ok((Primitive::Quadric(Arc::new(quadric)), allowed))
    }

    /// The `coefficients` object of a general quadric.
    fn quadric_coefficients(&self) -> R<QuadricCoefficients> {
        let i = self.at("coefficients")?;
        let Value::Object(entries) = &self.reader.doc.values[i as usize] else {
            return Err(self.fail(
                i,
                "coefficients",
                "expected an object of coefficients a … d",
            ));
        };
        let mut c = [0.0; 10];
        for (k, v) in entries {
            let Some(slot) = COEFFICIENT_KEYS.iter().position(|x| x == k) else {
                return Err(self.fail(
                    *v,
                    &format!("coefficients.{k}"),
                    format!(
                        "unknown coefficient \"{k}\" (expected one of: {})",
                        COEFFICIENT_KEYS.join(", ")
                    ),
                ));
            };
            c[slot] = self.number_at(*v, &format!("coefficients.{k}"))?;
        }
        let [a, b, c, f, g, h, p, q, r, d] = c;
        Ok(QuadricCoefficients {
            a,
            b,
            c,
            f,
            g,
            h,
            p,
            q,
            r,
            d,
        })
    }

    /// An optional box `[[x, y, z], [x, y, z]]` under `key`.
    pub(super) fn quadric_bounds(&self, key: &str) -> R<Option<Aabb>> {
        let Some((_, i)) = self.entries.iter().find(|(k, _)| k == key) else {
            return Ok(None);
        };
        let Value::Array(corners) = &self.reader.doc.values[*i as usize] else {
            return Err(self.fail(*i, key, "expected [[min x, y, z], [max x, y, z]]"));
        };
        if corners.len() != 2 {
            return Err(self.fail(*i, key, "expected [[min x, y, z], [max x, y, z]]"));
        }
        let min = DVec3::from_array(self.numbers::<3>(corners[0], key)?);
        let max = DVec3::from_array(self.numbers::<3>(corners[1], key)?);
        Ok(Some(Aabb::new(min, max)))
    }
}
