//! The polyhedral track of the conversion (`--method polyhedral`): beside each statement's
//! field solid, the polyhedron OpenSCAD builds for it, combined by mesh Booleans
//! (`solidkit_meshing::polyhedral`) as OpenSCAD's CGAL render and manifold3d do. Round
//! primitives are OpenSCAD's faceted ones here whatever `--facets` says; extrusions are its
//! slices (`sliced.rs`) of the 2D region's polygons (`region.rs`), turns its straight steps
//! (`turned.rs`); `hull` and `minkowski` take the convex pieces the field track found, and
//! imported meshes, polyhedra and `surface` their own triangles, `resize` the polyhedron's box,
//! `projection` the polyhedron's section or shadow. A statement with no polyhedral form (a wedge
//! extruded to a segment, a `hull` of operands the field track cannot enumerate) says which and
//! where; the conversion then meshes that statement's field alone on a grid (`convert_with`'s
//! `part_grid`) or, without one, leaves the model without a polyhedron.

use super::facets;
use super::flat::Flat;
use super::geom::Geom;
use super::hullable::Hullable;
use super::parser::Stmt;
use super::region;
use super::shape_args::{cylinder_params, matrix, radius};
use super::sliced;
use super::turned;
use super::{Facets, Pos};
use glam::{DAffine3, DMat3, DVec2, DVec3};
use solidkit_meshing::polyhedral::{
    Polyhedral, difference, from_solid, intersection_all, union_all,
};

/// Why a statement has no polyhedral form, and where it is.
#[derive(Debug, Clone)]
pub struct NotPolyhedral {
    /// Where the statement starts.
    pub pos: Pos,
    /// What has no polyhedral form.
    pub message: String,
}

impl std::fmt::Display for NotPolyhedral {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {} has no polyhedral form", self.pos, self.message)
    }
}

/// A 3D statement's polyhedron, or why it has none.
pub(super) type Track = Result<Polyhedral, NotPolyhedral>;

/// What a child converted to, kept before the field track consumes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Dim {
    Empty,
    Solid,
    Flat,
}

/// The dimension of each child's geometry.
pub(super) fn dims(children: &[Geom]) -> Vec<Dim> {
    children
        .iter()
        .map(|g| match g {
            Geom::Empty => Dim::Empty,
            Geom::Solid(_) => Dim::Solid,
            Geom::Flat(_) => Dim::Flat,
        })
        .collect()
}

/// The union of the 2D children (for extrusions), before the field track consumes them.
pub(super) fn flat_of(children: &[Geom]) -> Option<Flat> {
    let flats: Vec<Flat> = children
        .iter()
        .filter_map(|g| match g {
            Geom::Flat(f) => Some(f.clone()),
            _ => None,
        })
        .collect();
    (!flats.is_empty()).then(|| Flat::combine(flats, super::flat::Op2::Union))
}

/// The statement's polyhedron from its children's (`kids`, `None` for 2D or skipped ones), its
/// own arguments and what the field track made of it (`geom`; `info` for `hull` and
/// `minkowski`). `None` when the statement is not 3D.
pub(super) fn track(
    stmt: &Stmt,
    dims: &[Dim],
    kids: Vec<Option<Track>>,
    flat: Option<&Flat>,
    geom: &Geom,
    info: Option<&Hullable>,
) -> Option<Track> {
    match geom {
        Geom::Flat(_) => None,
        Geom::Empty => Some(Ok(Polyhedral::empty())),
        Geom::Solid(solid) => Some(solid_track(stmt, dims, kids, flat, info).or_else(|e| {
            // Statements the field track built as polyhedra (`polyhedron`, `import`, `resize`
            // of them) are their own triangles.
            if matches!(
                stmt.name.as_str(),
                "polyhedron" | "import" | "resize" | "surface"
            ) {
                from_solid(solid).map_err(|_| e)
            } else {
                Err(e)
            }
        })),
    }
}

fn not(stmt: &Stmt, message: impl Into<String>) -> NotPolyhedral {
    NotPolyhedral {
        pos: stmt.pos,
        message: message.into(),
    }
}

fn faces(stmt: &Stmt, (v, f): (Vec<DVec3>, Vec<Vec<u32>>)) -> Track {
    Polyhedral::from_faces(v, f).map_err(|e| not(stmt, format!("`{}`: {e}", stmt.name)))
}

fn solid_track(
    stmt: &Stmt,
    dims: &[Dim],
    kids: Vec<Option<Track>>,
    flat: Option<&Flat>,
    info: Option<&Hullable>,
) -> Track {
    let failed = |e: solidkit_meshing::polyhedral::PolyhedralError| not(stmt, e.to_string());
    let res = || stmt.resolution().map_err(|e| not(stmt, e.to_string()));
    match stmt.name.as_str() {
        "group" | "union" | "render" | "color" => union_all(operands(dims, kids)?).map_err(failed),
        "difference" => {
            let mut parts = operands(dims, kids)?.into_iter();
            let base = parts.next().unwrap_or_else(Polyhedral::empty);
            difference(base, parts.collect()).map_err(failed)
        }
        "intersection" => intersection_all(operands(dims, kids)?).map_err(failed),
        "multmatrix" => {
            let m = matrix(stmt).map_err(|e| not(stmt, e.to_string()))?;
            let row = |i: usize| DVec3::new(m[i][0], m[i][1], m[i][2]);
            let a = DAffine3 {
                matrix3: DMat3::from_cols(row(0), row(1), row(2)).transpose(),
                translation: DVec3::new(m[0][3], m[1][3], m[2][3]),
            };
            Ok(union_all(operands(dims, kids)?)
                .map_err(failed)?
                .transform(&a))
        }
        "cube" => {
            let size = stmt
                .size3("size", Some(0), 1.0)
                .map_err(|e| not(stmt, e.to_string()))?;
            let centred = stmt
                .flag("center", Some(1), false)
                .map_err(|e| not(stmt, e.to_string()))?;
            let lo = if centred { -size / 2.0 } else { DVec3::ZERO };
            Polyhedral::cuboid(lo, size).map_err(failed)
        }
        "sphere" => {
            let r = radius(stmt, "r", "d", 0, 1.0).map_err(|e| not(stmt, e.to_string()))?;
            faces(stmt, facets::sphere(r, res()?))
        }
        "cylinder" => match cylinder_params(stmt).map_err(|e| not(stmt, e.to_string()))? {
            Some((r1, r2, z0, h)) => faces(stmt, facets::cylinder(r1, r2, z0, z0 + h, res()?)),
            None => Ok(Polyhedral::empty()),
        },
        "resize" => resize(stmt, union_all(operands(dims, kids)?).map_err(failed)?),
        "linear_extrude" => linear_extrude(stmt, flat.ok_or_else(|| not(stmt, "no profile"))?),
        "rotate_extrude" => rotate_extrude(stmt, flat.ok_or_else(|| not(stmt, "no profile"))?),
        "hull" | "minkowski" => {
            let pieces = info
                .and_then(|i| i.pieces.as_ref())
                .ok_or_else(|| not(stmt, format!("`{}` of these operands", stmt.name)))?;
            let hulls = pieces
                .iter()
                .map(|p| Polyhedral::hull(p))
                .collect::<Result<Vec<_>, _>>()
                .map_err(failed)?;
            union_all(hulls).map_err(failed)
        }
        other => Err(not(stmt, format!("`{other}`"))),
    }
}

/// The union of the top-level statements (an implicit group).
pub(super) fn union_track(dims: &[Dim], kids: Vec<Option<Track>>) -> Track {
    union_all(operands(dims, kids)?).map_err(|e| NotPolyhedral {
        pos: Pos::default(),
        message: e.to_string(),
    })
}

/// The 3D children a group combines: as in the field track, the first non-empty child sets the
/// dimension and the others are ignored.
fn operands(dims: &[Dim], kids: Vec<Option<Track>>) -> Result<Vec<Polyhedral>, NotPolyhedral> {
    let first = dims.iter().find(|d| **d != Dim::Empty);
    if first != Some(&Dim::Solid) {
        return Ok(Vec::new());
    }
    let mut out = Vec::new();
    for (d, k) in dims.iter().zip(kids) {
        if *d == Dim::Solid
            && let Some(t) = k
        {
            out.push(t?);
        }
    }
    Ok(out)
}

/// Every loop of the 2D region, as OpenSCAD's polygons, corners on a grid ([`snapped`]): an
/// offset's clipping leaves corners 10⁻¹⁵ apart and slivers of no area, which the triangulator
/// refuses and OpenSCAD's own 2D grid merges.
fn loops_of(stmt: &Stmt, flat: &Flat) -> Result<Vec<Vec<DVec2>>, NotPolyhedral> {
    let shapes = region::shapes(flat, Facets::OpenScad).map_err(|e| not(stmt, e.to_string()))?;
    let clean = region::positive(snapped(shapes.into_iter().flatten().collect()))
        .map_err(|e| not(stmt, e.to_string()))?;
    Ok(clean.into_iter().flatten().collect())
}

fn linear_extrude(stmt: &Stmt, flat: &Flat) -> Track {
    let arg = |e: super::error::CsgError| not(stmt, e.to_string());
    let h = stmt.num("height", Some(0), 100.0).map_err(arg)?;
    let twist = stmt.num("twist", None, 0.0).map_err(arg)?;
    let scale = stmt.size2("scale", None, 1.0).map_err(arg)?;
    let centred = stmt.flag("center", None, false).map_err(arg)?;
    let loops = loops_of(stmt, flat)?;
    if loops.is_empty() {
        return Ok(Polyhedral::empty());
    }
    let slices = if twist == 0.0 && scale.x == scale.y {
        1.0
    } else {
        let given = match stmt.arg("slices", None) {
            Some(super::parser::Value::Num(n)) if n.is_finite() => Some(*n),
            _ => None,
        };
        let reach = sliced::Reach::of(&loops, scale);
        sliced::slice_count(
            given,
            h,
            twist,
            scale,
            stmt.resolution().map_err(arg)?,
            reach,
        )
    };
    let mesh = sliced::sliced_extrusion(&loops, h, twist, scale, slices as usize)
        .ok_or_else(|| not(stmt, "`linear_extrude` to a segment or of this profile"))?;
    let p = faces(stmt, mesh)?;
    Ok(if centred {
        p
    } else {
        p.transform(&DAffine3::from_translation(DVec3::new(0.0, 0.0, h / 2.0)))
    })
}

/// `resize` of a polyhedron: scaled about the origin so that its own bounding box gets the new
/// size, with OpenSCAD's rules for zero and `auto` (`resize.rs`).
fn resize(stmt: &Stmt, p: Polyhedral) -> Track {
    let (newsize, auto) = super::resize::arguments(stmt).map_err(|e| not(stmt, e.to_string()))?;
    if newsize.iter().any(|v| !v.is_finite()) {
        return Ok(Polyhedral::empty());
    }
    let Some((lo, hi)) = p.bounds() else {
        return Ok(p);
    };
    Ok(match super::resize::factors(newsize, auto, hi - lo, 3) {
        Some(k) if k != DVec3::ONE => p.transform(&DAffine3::from_scale(k)),
        _ => p,
    })
}

fn rotate_extrude(stmt: &Stmt, flat: &Flat) -> Track {
    let arg = |e: super::error::CsgError| not(stmt, e.to_string());
    let angle = stmt
        .num("angle", None, 360.0)
        .map_err(arg)?
        .clamp(-360.0, 360.0);
    let mut loops = loops_of(stmt, flat)?;
    let (lo, hi) = loops
        .iter()
        .flatten()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.x), hi.max(p.x))
        });
    if loops.is_empty() || angle == 0.0 || (lo < 0.0 && hi > 0.0) {
        return Ok(Polyhedral::empty());
    }
    let mirrored = lo < 0.0;
    if mirrored {
        for p in loops.iter_mut().flatten() {
            p.x = -p.x;
        }
    }
    let fragments = facets::fragments(hi.max(0.0) - lo.min(0.0), stmt.resolution().map_err(arg)?);
    let mesh = if angle.abs() == 360.0 {
        turned::full_turn(&loops, fragments, 180.0)
    } else {
        turned::stepped_turn(&loops, angle.abs(), turned::step_count(fragments, angle))
    }
    .ok_or_else(|| not(stmt, "`rotate_extrude` of this profile"))?;
    let mut p = faces(stmt, mesh)?;
    if mirrored {
        p = p.transform(&DAffine3::from_rotation_z(std::f64::consts::PI));
    }
    if angle < 0.0 {
        p = p.transform(&DAffine3::from_scale(DVec3::new(1.0, -1.0, 1.0)));
    }
    Ok(p)
}

/// `projection` of the 3D children's polyhedra, exact: the section by z = 0 (`cut`) or the
/// shadow, from the polyhedron's own edges. `Some(None)` for an empty result; `None` when a 3D
/// child has no polyhedron or the kernel fails, and the field track samples it instead.
pub(super) fn projection(
    stmt: &Stmt,
    dims: &[Dim],
    kids: &mut [Option<Track>],
) -> Option<Option<Flat>> {
    let mut solids = Vec::new();
    for (d, k) in dims.iter().zip(kids.iter_mut()) {
        if *d == Dim::Solid {
            solids.push(k.take()?.ok()?);
        }
    }
    let cut = stmt.flag("cut", Some(0), false).ok()?;
    let solid = union_all(solids).ok()?;
    let loops = if cut {
        solid.section_at_zero()
    } else {
        solid.shadow()
    }
    .ok()?;
    Some(region::to_flat(region::positive(snapped(loops)).ok()?))
}

/// The loops' corners rounded to a grid of 2⁻²⁰ of their extent (a power of two, so exact).
/// A shadow unites many faces' outlines, and its corners can come out closer than single
/// precision tells apart (STL's): such near twins, written to an STL, become one vertex and
/// fold the extruded walls onto each other. On the grid they are one corner, and pieces whose
/// edges nearly touch share them, which the union then joins (OpenSCAD's own 2D grid is 2⁻¹⁶
/// model units).
fn snapped(mut loops: Vec<Vec<DVec2>>) -> Vec<Vec<DVec2>> {
    let reach = loops
        .iter()
        .flatten()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    if reach > 0.0 {
        let step = (reach * 2f64.powi(-20)).log2().floor().exp2();
        for p in loops.iter_mut().flatten() {
            *p = (*p / step).round() * step;
        }
    }
    loops
}
