//! `solidkit curve`: a JSON curve file → point and derivatives at a parameter, the de Casteljau
//! split of the Bézier piece at a parameter, arc length, and a polyline file within a
//! chord-error bound (or with a number of equally spaced samples).

mod polyline;

use crate::args::CurveArgs;
use crate::output::outln;
use anyhow::{Result, anyhow, bail};
use glam::DVec3;
use serde_json::{Value, json};
use solidkit_kernel::KernelError;
use solidkit_kernel::curve::flatten::uniform_params;
use solidkit_kernel::curve::{BezierPiece, Parametric, Polyline};

/// Reads the curve, prints what was asked and writes the polyline; exit code 0.
pub fn run(a: &CurveArgs) -> Result<u8> {
    let name = a.curve.display().to_string();
    let text = std::fs::read_to_string(&a.curve).map_err(|e| anyhow!("{name}: {e}"))?;
    let curve = solidkit_kernel::json::curve_from_str(&text).map_err(|e| match e {
        KernelError::Json {
            line,
            column,
            message,
        } => anyhow!("{name}:{line}:{column}: {message}"),
        other => anyhow!("{name}: {other}"),
    })?;
    let (t0, t1) = curve.domain();
    let check = |flag: &str, u: f64| -> Result<f64> {
        if u.is_finite() && u >= t0 && u <= t1 {
            Ok(u)
        } else {
            bail!("{flag} {u}: outside the curve's domain [{t0}, {t1}] ({name})")
        }
    };
    let at = a.at.map(|u| check("--at", u)).transpose()?;
    let split_at = a.split.map(|u| check("--split", u)).transpose()?;
    let split = match split_at {
        Some(u) => Some(curve.split(u).ok_or_else(|| {
            anyhow!("--split: a formula curve has no control points to split ({name})")
        })?),
        None => None,
    };
    let written = match &a.output {
        Some(path) => {
            let line = polyline_of(&curve, a)?;
            polyline::write(path, &line)?;
            Some((path.display().to_string(), line))
        }
        None => None,
    };
    let mut report = json!({
        "file": name,
        "type": curve.name(),
        "domain": [t0, t1],
        "closed": curve.is_closed(),
        "arc_length": curve.arc_length(),
    });
    if let Some(u) = at {
        let j = curve.jet(u);
        let mut point = json!({"u": u, "point": v3(j.point)});
        if a.tangent {
            point["d1"] = v3(j.d1);
            point["d2"] = v3(j.d2);
            point["unit_tangent"] = v3(j.d1.normalize_or_zero());
        }
        report["at"] = point;
    }
    if let (Some(u), Some(s)) = (split_at, &split) {
        report["split"] = json!({
            "u": u,
            "piece": s.piece,
            "interval": [s.interval.0, s.interval.1],
            "local": s.local,
            "left": piece_json(&s.left),
            "right": piece_json(&s.right),
        });
    }
    if let Some((path, line)) = &written {
        report["polyline"] = json!({
            "path": path,
            "points": line.points.len(),
            "bound": bound_name(a, line),
            "chord_error": chord_error(&curve, a),
        });
    }
    if a.json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        text_report(&report)?;
    }
    Ok(0)
}

/// The chord-error bound asked for (or its default: 1e-4 of the curve's size).
fn chord_error(curve: &Parametric, a: &CurveArgs) -> Option<f64> {
    if a.samples.is_some() {
        return None;
    }
    Some(a.chord_error.unwrap_or(1e-4 * curve.size()))
}

fn bound_name(a: &CurveArgs, line: &Polyline) -> &'static str {
    match (a.samples, line.certified) {
        (Some(_), _) => "samples",
        (None, true) => "certified",
        (None, false) => "estimated",
    }
}

/// The polyline asked for: equally spaced samples, or within the chord-error bound.
fn polyline_of(curve: &Parametric, a: &CurveArgs) -> Result<Polyline> {
    let line = match a.samples {
        Some(n) => {
            let params = uniform_params(curve.domain(), n as usize);
            let points = params.iter().map(|&u| curve.point(u)).collect();
            Polyline {
                params,
                points,
                certified: false,
            }
        }
        None => {
            if a.chord_error.is_none() && !curve.size().is_finite() {
                bail!(
                    "the curve has a point that is not finite, so it has no size for the \
                     default chord error: check its formulas"
                );
            }
            let tolerance = chord_error(curve, a).unwrap_or(0.0);
            if !(tolerance.is_finite() && tolerance > 0.0) {
                bail!("--chord-error {tolerance}: expected a positive number");
            }
            curve
                .polyline(tolerance)
                .map_err(|e| anyhow!("--chord-error: {e}"))?
        }
    };
    if let Some(p) = line.points.iter().find(|p| !p.is_finite()) {
        bail!("the curve has a point that is not finite ({p}): check its formulas");
    }
    Ok(line)
}

fn v3(p: DVec3) -> Value {
    json!([p.x, p.y, p.z])
}

/// Control points (projected) and weights of a Bézier piece.
fn piece_json(p: &BezierPiece) -> Value {
    let points: Vec<Value> = p.projected().map(v3).collect();
    let weights: Vec<f64> = p.points.iter().map(|q| q.w).collect();
    let mut v = json!({"interval": [p.t0, p.t1], "points": points});
    if weights.iter().any(|&w| w != 1.0) {
        v["weights"] = json!(weights);
    }
    v
}

/// `[x, y, z]` of a JSON point.
fn show(v: &Value) -> String {
    match v.as_array() {
        Some(xs) => {
            let parts: Vec<String> = xs.iter().map(|x| x.to_string()).collect();
            format!("({})", parts.join(", "))
        }
        None => v.to_string(),
    }
}

fn points_line(v: &Value) -> String {
    v.as_array()
        .map(|ps| ps.iter().map(show).collect::<Vec<_>>().join(" "))
        .unwrap_or_default()
}

fn text_report(r: &Value) -> Result<()> {
    outln!(
        "curve: {} ({}), domain {}, closed: {}",
        r["type"].as_str().unwrap_or(""),
        r["file"].as_str().unwrap_or(""),
        show(&r["domain"]).replace('(', "[").replace(')', "]"),
        if r["closed"] == true { "yes" } else { "no" }
    )?;
    outln!("arc length: {}", r["arc_length"])?;
    if let Some(at) = r.get("at") {
        outln!("at u = {}: point {}", at["u"], show(&at["point"]))?;
        if at.get("d1").is_some() {
            outln!("  first derivative {}", show(&at["d1"]))?;
            outln!("  second derivative {}", show(&at["d2"]))?;
            outln!("  unit tangent {}", show(&at["unit_tangent"]))?;
        }
    }
    if let Some(s) = r.get("split") {
        outln!(
            "split at u = {}: Bézier piece {} over {}, local parameter {}",
            s["u"],
            s["piece"],
            show(&s["interval"]).replace('(', "[").replace(')', "]"),
            s["local"]
        )?;
        for side in ["left", "right"] {
            outln!("  {side}: {}", points_line(&s[side]["points"]))?;
            if let Some(w) = s[side].get("weights") {
                outln!("  {side} weights: {}", show(w))?;
            }
        }
    }
    if let Some(p) = r.get("polyline") {
        let bound = match p["bound"].as_str() {
            Some("samples") => "equally spaced samples".to_string(),
            Some(b) => format!("chord error <= {} ({b})", p["chord_error"]),
            None => String::new(),
        };
        outln!(
            "polyline: {} points, {bound}; wrote: {}",
            p["points"],
            p["path"].as_str().unwrap_or("")
        )?;
    }
    Ok(())
}
