//! The `platonic` suite: the five Platonic solids (edge 1), their duals (built on the face
//! centroids, so each dual is the dual kind with circumradius equal to the original's inradius)
//! and four prisms (triangle, hexagon, five-pointed star, square frame with a square hole), all
//! as exact polyhedral meshes centred at the origin.
//!
//! Truth: counts of the triangulated polyhedron from formulas (a Platonic solid with `F` faces of
//! `s` sides has `F(s − 2)` triangles; a prism over `n` loop points with `h` holes has `2n`
//! vertices and `2(n + 2h − 2) + 2n` triangles), genus and χ from the construction, volume and
//! area in closed form ([`PlatonicKind::unit_measures`]; prisms: cross-section area × height and
//! `2A + perimeter × height`), bounding box from the exact vertices.

use super::truth::{Quantity, Truth, TruthMethod};
use super::{GenSolid, SuiteError, build_error};
use glam::{DVec2, DVec3};
use serde_json::json;
use solidkit_kernel::polyhedra::{PlatonicKind, PlatonicSize, Polyhedron, Prism};
use std::f64::consts::TAU;

/// Edge length of the Platonic solids.
pub const EDGE: f64 = 1.0;
/// Height of the prisms.
pub const PRISM_HEIGHT: f64 = 1.0;

/// The suite's solids: five Platonic solids, five duals, four prisms.
pub fn solids() -> Result<Vec<GenSolid>, SuiteError> {
    let mut out = Vec::new();
    for kind in PlatonicKind::ALL {
        out.push(platonic(kind)?);
    }
    for kind in PlatonicKind::ALL {
        out.push(dual(kind)?);
    }
    for (name, description, polygon, holes) in prism_shapes() {
        out.push(prism(name, description, polygon, holes)?);
    }
    Ok(out)
}

/// Bounding box of the polyhedron's vertices.
fn bbox(p: &Polyhedron) -> ([f64; 3], [f64; 3]) {
    let lo = p.vertices().iter().fold(DVec3::INFINITY, |m, v| m.min(*v));
    let hi = p
        .vertices()
        .iter()
        .fold(DVec3::NEG_INFINITY, |m, v| m.max(*v));
    (lo.to_array(), hi.to_array())
}

/// Truth of a Platonic solid of kind `kind` with edge `edge`.
fn platonic_truth(kind: PlatonicKind, edge: f64, p: &Polyhedron) -> Truth {
    let m = kind.unit_measures();
    let triangles = (m.counts[2] * (m.face_sides - 2)) as u64;
    let (lo, hi) = bbox(p);
    Truth {
        volume: Some(Quantity::closed_form(m.volume * edge.powi(3))),
        area: Some(Quantity::closed_form(m.area * edge * edge)),
        ..Truth::default()
    }
    .with_topology(1, 0, TruthMethod::ExactPolyhedron)
    .with_closed_counts(triangles)
    .with_bbox(lo, hi)
}

fn polyhedral(
    name: String,
    description: String,
    parameters: serde_json::Value,
    p: &Polyhedron,
    truth: Truth,
) -> GenSolid {
    GenSolid {
        name,
        description,
        parameters,
        mesh: p.to_indexed(),
        truth,
        chord_error_bound: Some(0.0),
        volume_tolerance: None,
        tree: None,
        defects: None,
    }
}

fn platonic(kind: PlatonicKind) -> Result<GenSolid, SuiteError> {
    let name = kind.name();
    let p =
        Polyhedron::platonic(kind, PlatonicSize::Edge(EDGE)).map_err(|e| build_error(name, e))?;
    let truth = platonic_truth(kind, EDGE, &p);
    let m = kind.unit_measures();
    Ok(polyhedral(
        name.to_owned(),
        format!("regular {name} with edge {EDGE}, centred at the origin"),
        json!({"kind": name, "edge": EDGE, "circumradius": m.circumradius * EDGE}),
        &p,
        truth,
    ))
}

fn dual(kind: PlatonicKind) -> Result<GenSolid, SuiteError> {
    let name = format!("dual_of_{}", kind.name());
    let p = Polyhedron::platonic(kind, PlatonicSize::Edge(EDGE))
        .and_then(|p| p.dual())
        .map_err(|e| build_error(&name, e))?;
    let edge = kind.dual_edge(EDGE);
    let truth = platonic_truth(kind.dual(), edge, &p);
    Ok(polyhedral(
        name,
        format!(
            "dual of the {} of edge {EDGE} (vertices at its face centroids): a {} of edge {edge}",
            kind.name(),
            kind.dual().name()
        ),
        json!({"of": kind.name(), "of_edge": EDGE, "kind": kind.dual().name(), "edge": edge}),
        &p,
        truth,
    ))
}

/// A regular polygon of `n` corners on the circle of radius `r`, first corner on +x.
fn regular(n: usize, r: f64) -> Vec<DVec2> {
    (0..n)
        .map(|i| DVec2::from_angle(TAU * i as f64 / n as f64) * r)
        .collect()
}

type Shape = (&'static str, &'static str, Vec<DVec2>, Vec<Vec<DVec2>>);

/// The four prism cross-sections.
fn prism_shapes() -> Vec<Shape> {
    let star: Vec<DVec2> = (0..10)
        .map(|i| {
            let r = if i % 2 == 0 { 1.0 } else { 0.4 };
            DVec2::from_angle(TAU * i as f64 / 10.0 + TAU / 4.0) * r
        })
        .collect();
    let square = |h: f64| {
        vec![
            DVec2::new(-h, -h),
            DVec2::new(h, -h),
            DVec2::new(h, h),
            DVec2::new(-h, h),
        ]
    };
    vec![
        (
            "prism_triangle",
            "prism over an equilateral triangle of circumradius 1",
            regular(3, 1.0),
            vec![],
        ),
        (
            "prism_hexagon",
            "prism over a regular hexagon of circumradius 1",
            regular(6, 1.0),
            vec![],
        ),
        (
            "prism_star",
            "prism over a five-pointed star (radii 1 and 0.4; non-convex)",
            star,
            vec![],
        ),
        (
            "prism_square_hole",
            "prism over a 2 x 2 square with a 1 x 1 square hole (genus 1)",
            square(1.0),
            vec![square(0.5)],
        ),
    ]
}

fn prism(
    name: &str,
    description: &str,
    polygon: Vec<DVec2>,
    holes: Vec<Vec<DVec2>>,
) -> Result<GenSolid, SuiteError> {
    let h = PRISM_HEIGHT;
    // Centred on the origin: the prism runs from z = −h/2 to h/2.
    let prism = Prism::new(polygon.clone(), holes.clone(), DVec3::new(0.0, 0.0, h));
    let p = prism.to_polyhedron().map_err(|e| build_error(name, e))?;
    let p = Polyhedron::new(
        p.vertices()
            .iter()
            .map(|v| *v - DVec3::Z * (h / 2.0))
            .collect(),
        p.faces().to_vec(),
    )
    .map_err(|e| build_error(name, e))?;
    let loops: Vec<&Vec<DVec2>> = std::iter::once(&polygon).chain(&holes).collect();
    let n: usize = loops.iter().map(|l| l.len()).sum();
    let perimeter: f64 = loops
        .iter()
        .map(|l| {
            (0..l.len())
                .map(|i| l[i].distance(l[(i + 1) % l.len()]))
                .sum::<f64>()
        })
        .sum();
    let section = prism.cross_section_area();
    let genus = holes.len() as i64;
    let triangles = (2 * (n + 2 * holes.len() - 2) + 2 * n) as u64;
    let (lo, hi) = bbox(&p);
    let truth = Truth {
        volume: Some(Quantity::closed_form(section * h)),
        area: Some(Quantity::closed_form(2.0 * section + perimeter * h)),
        ..Truth::default()
    }
    .with_topology(1, genus, TruthMethod::ExactPolyhedron)
    .with_closed_counts(triangles)
    .with_bbox(lo, hi);
    let pts = |l: &Vec<DVec2>| l.iter().map(|q| [q.x, q.y]).collect::<Vec<_>>();
    Ok(polyhedral(
        name.to_owned(),
        format!("{description}, height {h}, centred at the origin"),
        json!({
            "polygon": pts(&polygon),
            "holes": holes.iter().map(pts).collect::<Vec<_>>(),
            "height": h,
        }),
        &p,
        truth,
    ))
}
