//! Writing the sweep family's parameters (the inverse of `read/sweep.rs`): profiles and curves
//! as nested objects, every number in shortest round-trip form, so reading back gives the same
//! primitive bit for bit.

use super::{num, vec3};
use crate::curve::Curve;
use crate::primitive::{Extrude, Loft, Revolve, Ruled, RuledSurface, Sweep};
use crate::profile::Profile;
use glam::DVec2;

fn vec2(v: DVec2) -> String {
    format!("[{}, {}]", num(v.x), num(v.y))
}

fn list<T>(items: &[T], f: impl Fn(&T) -> String) -> String {
    let parts: Vec<String> = items.iter().map(f).collect();
    format!("[{}]", parts.join(", "))
}

/// A profile object.
fn profile(p: &Profile) -> String {
    let body = match p {
        Profile::Circle(c) => format!(
            "\"radius\": {}, \"center\": {}",
            num(c.radius),
            vec2(c.center)
        ),
        Profile::Rectangle(r) => {
            format!("\"size\": {}, \"center\": {}", vec2(r.size), vec2(r.center))
        }
        Profile::Polygon(poly) => {
            let points = list(poly.points(), |q| vec2(*q));
            if poly.holes().is_empty() {
                format!("\"points\": {points}")
            } else {
                let holes = list(poly.holes(), |h| list(h, |q| vec2(*q)));
                format!("\"points\": {points}, \"holes\": {holes}")
            }
        }
    };
    format!("{{\"type\": \"{}\", {body}}}", p.name())
}

/// A curve object (a composite writes its pieces, which are never composite themselves).
fn curve(c: &Curve) -> String {
    match c {
        Curve::Composite(k) => {
            let pieces: Vec<String> = k.parts().iter().map(simple_curve).collect();
            let joins: Vec<String> = k
                .joins()
                .iter()
                .map(|j| format!("\"{}\"", j.name()))
                .collect();
            format!(
                "{{\"type\": \"composite\", \"pieces\": [{}], \"continuity\": [{}]}}",
                pieces.join(", "),
                joins.join(", ")
            )
        }
        _ => simple_curve(c),
    }
}

/// A curve object of any kind but composite.
fn simple_curve(c: &Curve) -> String {
    let points = |p: &[glam::DVec3]| list(p, |q| vec3(*q));
    let numbers = |x: &[f64]| list(x, |v| num(*v));
    let body = match c {
        Curve::Bezier(b) => format!("\"points\": {}", points(b.points())),
        Curve::Hermite(h) => format!(
            "\"points\": {}, \"tangents\": {}",
            points(h.points()),
            points(h.tangents())
        ),
        Curve::BSpline(b) => format!(
            "\"degree\": {}, \"points\": {}, \"knots\": {}",
            b.degree(),
            points(b.points()),
            numbers(b.knots())
        ),
        Curve::Nurbs(n) => format!(
            "\"degree\": {}, \"points\": {}, \"weights\": {}, \"knots\": {}",
            n.degree(),
            points(n.points()),
            numbers(n.weights()),
            numbers(n.knots())
        ),
        Curve::Interpolating(i) => format!(
            "\"points\": {}, \"closed\": {}",
            points(i.points()),
            i.closed()
        ),
        Curve::CubicThrough(t) => format!("\"points\": {}", points(t.points())),
        Curve::Composite(_) => unreachable!("Composite::new refuses composite pieces"),
    };
    format!("{{\"type\": \"{}\", {body}}}", c.name())
}

/// The members of an `extrude` node.
pub(super) fn extrude(e: &Extrude) -> String {
    format!(
        "\"profile\": {}, \"height\": {}, \"twist\": {}, \"scale\": {}",
        profile(e.profile()),
        num(e.height()),
        num(e.twist()),
        if e.scale().x == e.scale().y {
            num(e.scale().x)
        } else {
            vec2(e.scale())
        }
    )
}

/// The members of a `revolve` node.
pub(super) fn revolve(r: &Revolve) -> String {
    let steps = match r.segments() {
        Some((n, start)) => format!(", \"segments\": {n}, \"start\": {}", num(start)),
        None => String::new(),
    };
    format!(
        "\"profile\": {}, \"angle\": {}{steps}",
        profile(r.profile()),
        num(r.angle())
    )
}

/// The members of a `sweep` node.
pub(super) fn sweep(s: &Sweep) -> String {
    format!(
        "\"profile\": {}, \"path\": {}",
        profile(s.profile()),
        curve(s.path())
    )
}

/// The members of a `loft` node.
pub(super) fn loft(l: &Loft) -> String {
    format!(
        "\"bottom\": {}, \"top\": {}, \"height\": {}",
        profile(l.bottom()),
        profile(l.top()),
        num(l.height())
    )
}

/// The members of a `ruled` node.
pub(super) fn ruled(r: &Ruled) -> String {
    format!(
        "\"bottom\": {}, \"top\": {}",
        curve(r.bottom()),
        curve(r.top())
    )
}

/// The members of a `ruled_surface` node (`thickness` and `samples` when given or not the
/// default).
pub(super) fn ruled_surface(r: &RuledSurface) -> String {
    let mut s = format!(
        "\"first\": {}, \"second\": {}",
        curve(r.first()),
        curve(r.second())
    );
    if let Some(t) = r.thickness() {
        s += &format!(", \"thickness\": {}", num(t));
    }
    if r.samples() != RuledSurface::DEFAULT_SAMPLES {
        s += &format!(", \"samples\": {}", r.samples());
    }
    s
}
