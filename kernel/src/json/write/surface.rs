//! Writing the parametric surface nodes back as they were read (the inverse of
//! `read/surface.rs`): the surface's own keys, then `thickness` and `side` or `base`, then
//! `tolerance`, `tessellation` (when adaptive) and `segments` when given. B-spline and NURBS knots are always written.

use super::{num, string, vec3};
use crate::surface::{Closure, PnSource, SurfaceKind, SurfaceSpec, TensorSurface};
use glam::DVec3;

/// The parameter members of a surface node.
pub(super) fn members(spec: &SurfaceSpec) -> String {
    let mut out = match &spec.kind {
        SurfaceKind::Bezier(s) => format!("\"points\": {}", rows(s)),
        SurfaceKind::Interpolating(p) => {
            let r: Vec<String> = p.points().chunks(4).map(points).collect();
            format!("\"points\": [{}]", r.join(", "))
        }
        SurfaceKind::BSpline(s) | SurfaceKind::Nurbs(s) => {
            let [p, q] = s.degrees();
            let mut m = format!("\"degree\": [{p}, {q}], \"points\": {}", rows(s));
            if let Some(w) = s.weights() {
                let r: Vec<String> = w
                    .chunks(s.counts()[0])
                    .map(|row| list(row.iter().copied()))
                    .collect();
                m += &format!(", \"weights\": [{}]", r.join(", "));
            }
            let [ku, kv] = s.knots();
            m + &format!(
                ", \"knots_u\": {}, \"knots_v\": {}",
                list(ku.iter().copied()),
                list(kv.iter().copied())
            )
        }
        SurfaceKind::Formula(f) => {
            let mut m = String::new();
            for (key, text) in ["x", "y", "z"].iter().zip(f.formulas()) {
                if let Some(t) = text {
                    m += &format!("\"{key}\": {}, ", string(t));
                }
            }
            let (u, v) = f.ranges();
            m + &format!(
                "\"u\": {}, \"v\": {}",
                list(u.iter().copied()),
                list(v.iter().copied())
            )
        }
        SurfaceKind::Triangle(t) => {
            let n = t.degree();
            let mut pts = Vec::new();
            for k in 0..=n {
                for j in 0..=n - k {
                    pts.push(t.control(j, k));
                }
            }
            format!("\"degree\": {n}, \"points\": {}", points(&pts))
        }
        SurfaceKind::Pn(PnSource::File { path }) => format!("\"path\": {}", string(path)),
        SurfaceKind::Pn(PnSource::Inline {
            vertices,
            normals,
            triangles,
        }) => {
            let mut m = format!("\"vertices\": {}", points(vertices));
            if let Some(n) = normals {
                m += &format!(", \"normals\": {}", points(n));
            }
            let t: Vec<String> = triangles
                .iter()
                .map(|t| format!("[{}, {}, {}]", t[0], t[1], t[2]))
                .collect();
            m + &format!(", \"triangles\": [{}]", t.join(", "))
        }
    };
    match spec.closure {
        Closure::Closed => {}
        Closure::Thickness { thickness, side } => {
            out += &format!(
                ", \"thickness\": {}, \"side\": \"{}\"",
                num(thickness),
                side.name()
            );
        }
        Closure::Base { z } => out += &format!(", \"base\": {}", num(z)),
    }
    if let Some(t) = spec.tolerance {
        out += &format!(", \"tolerance\": {}", num(t));
    }
    if spec.adaptive {
        out += ", \"tessellation\": \"adaptive\"";
    }
    if let Some(s) = spec.segments {
        out += &format!(", \"segments\": {s}");
    }
    out
}

fn list(values: impl Iterator<Item = f64>) -> String {
    let v: Vec<String> = values.map(num).collect();
    format!("[{}]", v.join(", "))
}

fn points(p: &[DVec3]) -> String {
    let v: Vec<String> = p.iter().map(|p| vec3(*p)).collect();
    format!("[{}]", v.join(", "))
}

/// The control net as rows along `v` of points along `u`.
fn rows(s: &TensorSurface) -> String {
    let r: Vec<String> = s.points().chunks(s.counts()[0]).map(points).collect();
    format!("[{}]", r.join(", "))
}
