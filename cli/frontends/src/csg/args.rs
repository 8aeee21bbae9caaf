//! Typed access to a statement's arguments: named or positional, `undef` read as absent.

use super::error::CsgError;
use super::facets::{MAX_FRAGMENTS, Resolution};
use super::parser::{Stmt, Value};
use glam::{DVec2, DVec3};

impl Stmt {
    /// The argument `name`, or the `position`-th positional one; `undef` is `None`.
    pub fn arg(&self, name: &str, position: Option<usize>) -> Option<&Value> {
        let named = self
            .args
            .iter()
            .find(|a| a.name.as_deref() == Some(name))
            .map(|a| &a.value);
        let found = named.or_else(|| {
            position.and_then(|p| {
                self.args
                    .iter()
                    .filter(|a| a.name.is_none())
                    .nth(p)
                    .map(|a| &a.value)
            })
        });
        found.filter(|v| **v != Value::Undef)
    }

    /// An argument error of this statement.
    pub fn error(&self, message: impl Into<String>) -> CsgError {
        CsgError::argument(self.pos, &self.name, message)
    }

    /// A number argument, or `default` when absent.
    pub fn num(&self, name: &str, position: Option<usize>, default: f64) -> Result<f64, CsgError> {
        match self.arg(name, position) {
            None => Ok(default),
            Some(Value::Num(n)) if n.is_finite() => Ok(*n),
            Some(_) => Err(self.error(format!("'{name}': expected a finite number"))),
        }
    }

    /// A Boolean argument (numbers count as true when non-zero), or `default`.
    pub fn flag(
        &self,
        name: &str,
        position: Option<usize>,
        default: bool,
    ) -> Result<bool, CsgError> {
        match self.arg(name, position) {
            None => Ok(default),
            Some(Value::Bool(b)) => Ok(*b),
            Some(Value::Num(n)) => Ok(*n != 0.0),
            Some(_) => Err(self.error(format!("'{name}': expected true or false"))),
        }
    }

    /// `$fn`, `$fa`, `$fs` with OpenSCAD's defaults 0, 12, 2.
    pub fn resolution(&self) -> Result<Resolution, CsgError> {
        // A `$fn` of inf or nan means 3 fragments in OpenSCAD (see `facets::fragments`).
        let fn_ = match self.arg("$fn", None) {
            Some(Value::Num(n)) if !n.is_finite() => f64::NAN,
            _ => self.num("$fn", None, 0.0)?,
        };
        if fn_ > MAX_FRAGMENTS as f64 {
            return Err(self.error(format!(
                "'$fn' = {fn_}: more than {} fragments",
                MAX_FRAGMENTS
            )));
        }
        Ok(Resolution {
            fn_,
            fa: self.num("$fa", None, 12.0)?,
            fs: self.num("$fs", None, 2.0)?,
        })
    }

    /// A size that is either a number (all axes) or a vector of three numbers, or `default`.
    pub fn size3(
        &self,
        name: &str,
        position: Option<usize>,
        default: f64,
    ) -> Result<DVec3, CsgError> {
        match self.arg(name, position) {
            None => Ok(DVec3::splat(default)),
            Some(Value::Num(n)) => Ok(DVec3::splat(*n)),
            Some(v) => {
                let xs = numbers(v).filter(|xs| xs.len() == 3);
                xs.map(|x| DVec3::new(x[0], x[1], x[2]))
                    .ok_or_else(|| self.error(format!("'{name}': expected a number or [x, y, z]")))
            }
        }
    }

    /// A size that is either a number or a vector of two numbers, or `default`.
    pub fn size2(
        &self,
        name: &str,
        position: Option<usize>,
        default: f64,
    ) -> Result<DVec2, CsgError> {
        match self.arg(name, position) {
            None => Ok(DVec2::splat(default)),
            Some(Value::Num(n)) => Ok(DVec2::splat(*n)),
            Some(v) => {
                let xs = numbers(v).filter(|xs| xs.len() == 2);
                xs.map(|x| DVec2::new(x[0], x[1]))
                    .ok_or_else(|| self.error(format!("'{name}': expected a number or [x, y]")))
            }
        }
    }

    /// A list of points with `dim` coordinates each (2D points read with `dim = 3` get z = 0).
    pub fn points(
        &self,
        name: &str,
        position: Option<usize>,
        dim: usize,
    ) -> Result<Vec<DVec3>, CsgError> {
        let bad = || self.error(format!("'{name}': expected a list of points"));
        let Some(Value::Vector(items)) = self.arg(name, position) else {
            return Err(bad());
        };
        items
            .iter()
            .map(|p| {
                let xs = numbers(p).ok_or_else(bad)?;
                match (xs.len(), dim) {
                    (3, 3) => Ok(DVec3::new(xs[0], xs[1], xs[2])),
                    (2, _) => Ok(DVec3::new(xs[0], xs[1], 0.0)),
                    _ => Err(bad()),
                }
            })
            .collect()
    }

    /// A list of index lists (polyhedron faces, polygon paths), or `None` when absent.
    pub fn index_lists(
        &self,
        name: &str,
        position: Option<usize>,
    ) -> Result<Option<Vec<Vec<u32>>>, CsgError> {
        let bad = || self.error(format!("'{name}': expected a list of index lists"));
        let Some(v) = self.arg(name, position) else {
            return Ok(None);
        };
        let Value::Vector(items) = v else {
            return Err(bad());
        };
        items
            .iter()
            .map(|l| {
                numbers(l)
                    .filter(|xs| {
                        xs.iter()
                            .all(|&x| x >= 0.0 && x.fract() == 0.0 && x < u32::MAX as f64)
                    })
                    .map(|xs| xs.iter().map(|&x| x as u32).collect())
                    .ok_or_else(bad)
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }
}

/// The numbers of a flat vector of finite numbers.
pub fn numbers(v: &Value) -> Option<Vec<f64>> {
    let Value::Vector(items) = v else {
        return None;
    };
    items
        .iter()
        .map(|x| match x {
            Value::Num(n) if n.is_finite() => Some(*n),
            _ => None,
        })
        .collect()
}
