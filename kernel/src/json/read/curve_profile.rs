//! Profiles from curves: `{"type": "curve", "curve": CURVE, "chord_error": e}` (a closed curve of
//! any kind, projected on the xy plane) and `{"type": "radial", "rho": "formula in u",
//! "chord_error": e}` (the closed curve `ρ(u)·(cos u, sin u)`, `u ∈ [0, 2π]`: the radial equation
//! of a profile). Both become polygon profiles: the curve flattened with a chord error below `e`
//! (certified for curves with control points, estimated from samples for formulas; default
//! `1e-4` of the curve's size), so the polygon is within `e` of the curve everywhere; or, with
//! `"samples": n` instead, the `n` points at equally spaced parameters (the same corner count
//! for every profile, as `loft` needs).

use super::super::document::Value;
use super::sweep::Nested;
use super::{Params, R};
use crate::curve::flatten::uniform_params;
use crate::curve::{FormulaCurve, Parametric};
use crate::profile::Profile;
use glam::DVec2;

/// Relative chord error used when a curve profile gives none.
const DEFAULT_RELATIVE_CHORD_ERROR: f64 = 1e-4;

impl Params<'_, '_> {
    /// The polygon profile of a `curve` or `radial` profile object `n`.
    pub(super) fn curve_profile(&self, n: &Nested<'_>, ty: &str) -> R<Profile> {
        let k = |m: &str| format!("{}.{m}", n.key);
        let curve = if ty == "radial" {
            self.sweep_nested_keys(n, &["rho", "chord_error", "samples"])?;
            let i = self.sweep_member(n, "rho")?;
            let Value::String(rho) = &self.reader.doc.values[i as usize] else {
                return Err(self.fail(i, &k("rho"), "expected a formula string in u"));
            };
            let f = FormulaCurve::radial(rho).map_err(|e| self.fail(i, &k("rho"), e))?;
            Parametric::Formula(f)
        } else {
            self.sweep_nested_keys(n, &["curve", "chord_error", "samples"])?;
            let i = self.sweep_member(n, "curve")?;
            let Value::Object(entries) = &self.reader.doc.values[i as usize] else {
                return Err(self.fail(i, &k("curve"), "expected a curve object"));
            };
            self.curve_object(&Nested {
                index: i,
                entries,
                key: format!("{}.curve", n.key),
            })?
        };
        let at = super::find(n.entries, "curve")
            .or(super::find(n.entries, "rho"))
            .unwrap_or(n.index);
        if !curve.is_closed() {
            let (t0, t1) = curve.domain();
            return Err(self.fail(
                at,
                &n.key,
                format!(
                    "the curve must be closed: it starts at {:?} and ends at {:?}",
                    curve.point(t0).to_array(),
                    curve.point(t1).to_array()
                ),
            ));
        }
        let line = match super::find(n.entries, "samples") {
            Some(i) => {
                if let Some(j) = super::find(n.entries, "chord_error") {
                    return Err(self.fail(
                        j,
                        &k("chord_error"),
                        "give either chord_error or samples, not both",
                    ));
                }
                let count = self.number_at(i, &k("samples"))?;
                if !((3.0..=1e6).contains(&count) && count.fract() == 0.0) {
                    return Err(self.fail(
                        i,
                        &k("samples"),
                        "expected a whole number from 3 to 1000000",
                    ));
                }
                // `count` corners: the last parameter repeats the first point and is dropped.
                let params = uniform_params(curve.domain(), count as usize + 1);
                params.iter().map(|&u| curve.point(u)).collect::<Vec<_>>()
            }
            None => {
                let tolerance = match super::find(n.entries, "chord_error") {
                    Some(i) => {
                        let e = self.number_at(i, &k("chord_error"))?;
                        if !(e > 0.0 && e.is_finite()) {
                            return Err(self.fail(
                                i,
                                &k("chord_error"),
                                "expected a positive number",
                            ));
                        }
                        e
                    }
                    None => DEFAULT_RELATIVE_CHORD_ERROR * curve.size(),
                };
                curve
                    .polyline(tolerance)
                    .map_err(|e| self.fail(at, &k("chord_error"), e))?
                    .points
            }
        };
        if let Some(p) = line.iter().find(|p| !p.is_finite()) {
            return Err(self.fail(
                at,
                &n.key,
                format!("the curve has a point that is not finite: {p}"),
            ));
        }
        let mut points: Vec<DVec2> = line.iter().map(|p| p.truncate()).collect();
        points.pop(); // the closing point repeats the first
        Profile::polygon(points, Vec::new()).map_err(|e| self.sweep_profile_error(n, e))
    }
}
