//! The statement tree to a [`Solid`], post-order over an explicit work list: each statement's
//! geometry is built from its children's (3D solids, or 2D [`Flat`] programs under extrusions).

use super::Facets;
use super::args::numbers;
use super::error::{CsgError, Warning};
use super::facets;
use super::flat::{Flat, Leaf2, Op2, profile};
use super::hull::{convex_hull, convex_hull_2d, convex_hull_within};
use super::import::{Imported, import, string_arg};
use super::offset::{Offset, offset};
use super::parser::{Stmt, Tree, Value};
use super::pieces::{self, Piece};
use super::projection::projection;
use super::resize::resize;
use super::sliced;
use super::surface::surface;
use super::text::{TextCache, text};
use super::turned;
use glam::{DVec2, DVec3};
use solidkit_kernel::polyhedra::Polyhedron;
use solidkit_kernel::primitive::{Extrude, MeshResolver, Primitive, Revolve};
use solidkit_kernel::{IndexedMesh, Solid};
use solidkit_meshing::marching_cubes::GridSpec;
use solidkit_meshing::octree::{SparseOptions, mesh_sparse};
use std::sync::Arc;

/// A statement's geometry.
#[derive(Debug, Clone)]
pub(super) enum Geom {
    /// Nothing (an empty group, a zero-size primitive).
    Empty,
    /// A 3D solid.
    Solid(Solid),
    /// A 2D region.
    Flat(Flat),
}

/// What `hull()` and `minkowski()` know about a statement under them: the points whose convex
/// hull is the statement's hull (round primitives faceted the OpenSCAD way), and whether the
/// statement is convex itself.
#[derive(Debug, Clone)]
struct Hullable {
    points: Vec<DVec3>,
    convex: bool,
    /// The statement as convex pieces ([`super::pieces`]; 3D only), where known.
    pieces: Option<Vec<Piece>>,
}

/// How far the hull of meshed operand points may miss a point, in cells of the operand's grid:
/// the mesh vertices are only that accurate, and hulling them exactly gives thousands of sliver
/// faces along rounded-off edges.
const OPERAND_HULL_CELLS: f64 = 0.5;

/// The conversion's state: how round primitives are built, where imported files come from and
/// the warnings so far.
pub(super) struct Ctx<'a> {
    facets: Facets,
    files: &'a dyn MeshResolver,
    warnings: Vec<Warning>,
    /// `text()` drawings by their `.scad` source (OpenSCAD runs once per distinct text).
    texts: TextCache,
}

impl Ctx<'_> {
    pub(super) fn warn(&mut self, stmt: &Stmt, message: impl Into<String>) {
        self.warnings.push(Warning {
            pos: stmt.pos,
            message: message.into(),
        });
    }
}

/// Converts the whole tree (top-level statements form an implicit group): statements marked `%`
/// or `*` are left out, and the first statement marked `!` is the whole model. Parts OpenSCAD
/// skips with a warning are skipped here too, and their warnings returned.
pub fn convert(
    tree: &Tree,
    facets: Facets,
    files: &dyn MeshResolver,
) -> Result<(Solid, Vec<Warning>), CsgError> {
    let mut ctx = Ctx {
        facets,
        files,
        warnings: Vec::new(),
        texts: TextCache::default(),
    };
    // The arena is in document order, so the first `!` is the one with the smallest index.
    let marked: Vec<usize> = (0..tree.nodes.len())
        .filter(|&i| tree.nodes[i].modifiers.root)
        .collect();
    let roots: Vec<usize> = match marked.first() {
        Some(&r) => {
            if marked.len() > 1 {
                ctx.warn(
                    &tree.nodes[marked[1]],
                    "more than one root modifier (!): the first one is the model",
                );
            }
            vec![r]
        }
        None => tree.roots.clone(),
    };
    let kept = |i: &usize| !tree.nodes[*i].modifiers.dropped();
    let roots: Vec<usize> = roots.into_iter().filter(kept).collect();
    let mut results: Vec<Option<Geom>> = vec![None; tree.nodes.len()];
    let mut hullable: Vec<Option<Hullable>> = vec![None; tree.nodes.len()];
    // (statement, children done, under a hull or minkowski).
    let mut work: Vec<(usize, bool, bool)> =
        roots.iter().rev().map(|&r| (r, false, false)).collect();
    while let Some((i, expanded, hulled)) = work.pop() {
        let stmt = &tree.nodes[i];
        let kids: Vec<usize> = stmt.children.iter().copied().filter(kept).collect();
        if !expanded {
            work.push((i, true, hulled));
            let h = hulled || matches!(stmt.name.as_str(), "hull" | "minkowski");
            work.extend(kids.iter().rev().map(|&c| (c, false, h)));
            continue;
        }
        let children: Vec<Geom> = kids
            .iter()
            .map(|&c| results[c].take().expect("child converted"))
            .collect();
        let infos: Vec<Option<Hullable>> = kids.iter().map(|&c| hullable[c].take()).collect();
        let (geom, info) = match stmt.name.as_str() {
            "hull" => hull(stmt, children, infos, &mut ctx)?,
            "minkowski" => minkowski(tree, &kids, stmt, children, infos, &mut ctx)?,
            _ => {
                let facets = if hulled { Facets::OpenScad } else { facets };
                let geom = node(stmt, children, facets, &mut ctx)?;
                let info = if hulled {
                    hullable_of(stmt, &geom, infos)?
                } else {
                    None
                };
                (geom, info)
            }
        };
        results[i] = Some(geom);
        if hulled {
            hullable[i] = info;
        }
    }
    let top: Vec<Geom> = roots
        .iter()
        .map(|&r| results[r].take().expect("root converted"))
        .collect();
    let root = Stmt {
        name: "group".into(),
        ..Stmt::default()
    };
    let solid = match group(&root, top, Op2::Union, &mut ctx)? {
        Geom::Solid(s) => s,
        Geom::Empty => return Err(CsgError::Empty),
        Geom::Flat(_) => return Err(CsgError::Flat),
    };
    Ok((solid, ctx.warnings))
}

/// The non-empty children combined: solids by union / `difference` / intersection, 2D regions
/// by the same operation in 2D. As in OpenSCAD, the first non-empty child sets the dimension and
/// children of the other dimension are ignored with a warning.
fn group(
    stmt: &Stmt,
    children: Vec<Geom>,
    op: fn(usize) -> Op2,
    ctx: &mut Ctx,
) -> Result<Geom, CsgError> {
    let mut solids = Vec::new();
    let mut flats = Vec::new();
    let mut ignored = false;
    for (k, c) in children.into_iter().enumerate() {
        match c {
            Geom::Empty if k == 0 && matches!(op(0), Op2::Difference(_)) => return Ok(Geom::Empty),
            Geom::Empty if matches!(op(0), Op2::Intersection(_)) => return Ok(Geom::Empty),
            Geom::Empty => {}
            Geom::Solid(_) if !flats.is_empty() => ignored = true,
            Geom::Flat(_) if !solids.is_empty() => ignored = true,
            Geom::Solid(s) => solids.push(s),
            Geom::Flat(f) => flats.push(f),
        }
    }
    if ignored {
        let (kept, dropped) = if solids.is_empty() {
            ("2D", "3D")
        } else {
            ("3D", "2D")
        };
        ctx.warn(
            stmt,
            format!(
                "mixing 2D and 3D objects is not supported: the first child is {kept}, \
                 the {dropped} children are ignored"
            ),
        );
    }
    if !flats.is_empty() {
        return Ok(Geom::Flat(Flat::combine(flats, op)));
    }
    if solids.len() <= 1 {
        return Ok(solids.pop().map_or(Geom::Empty, Geom::Solid));
    }
    Ok(Geom::Solid(match op(0) {
        Op2::Difference(_) => {
            let base = solids.remove(0);
            Solid::difference_all(base, solids)
        }
        Op2::Intersection(_) => Solid::intersection_all(solids),
        _ => Solid::union_all(solids),
    }))
}

/// The union of the 2D children of an extrusion: 3D children are ignored with a warning (as
/// OpenSCAD does); `None` when nothing 2D is left.
fn flat_children(stmt: &Stmt, children: Vec<Geom>, ctx: &mut Ctx) -> Option<Flat> {
    let mut flats = Vec::new();
    let mut ignored = false;
    for c in children {
        match c {
            Geom::Flat(f) => flats.push(f),
            Geom::Solid(_) => ignored = true,
            Geom::Empty => {}
        }
    }
    if ignored {
        ctx.warn(stmt, "ignoring 3D child object for 2D operation");
    }
    (!flats.is_empty()).then(|| Flat::combine(flats, Op2::Union))
}

/// Whether any argument other than `$fn`, `$fa`, `$fs` holds `inf` or `nan` (at any depth).
fn non_finite(stmt: &Stmt) -> bool {
    let mut stack: Vec<&Value> = stmt
        .args
        .iter()
        .filter(|a| !a.name.as_deref().is_some_and(|n| n.starts_with('$')))
        .map(|a| &a.value)
        .collect();
    while let Some(v) = stack.pop() {
        match v {
            Value::Num(n) if !n.is_finite() => return true,
            Value::Vector(items) => stack.extend(items),
            _ => {}
        }
    }
    false
}

/// One statement from its children's geometry.
fn node(
    stmt: &Stmt,
    children: Vec<Geom>,
    facets: Facets,
    ctx: &mut Ctx<'_>,
) -> Result<Geom, CsgError> {
    let faceted = facets == Facets::OpenScad;
    let primitive = matches!(
        stmt.name.as_str(),
        "sphere" | "cube" | "cylinder" | "polyhedron" | "circle" | "square" | "polygon"
    );
    if primitive && non_finite(stmt) {
        ctx.warn(stmt, "a size or point is inf or nan: the object is skipped");
        return Ok(Geom::Empty);
    }
    if matches!(stmt.name.as_str(), "polyhedron" | "polygon")
        && stmt.arg("points", Some(0)).is_none()
    {
        ctx.warn(stmt, "'points' is undef: the object is skipped");
        return Ok(Geom::Empty);
    }
    let leaf = |what: Geom| {
        if stmt.children.is_empty() {
            Ok(what)
        } else {
            Err(stmt.error("takes no children"))
        }
    };
    match stmt.name.as_str() {
        "group" | "union" | "render" => group(stmt, children, Op2::Union, ctx),
        "color" => {
            let color = super::color::color_of(stmt).unwrap_or_else(|w| {
                ctx.warn(stmt, w);
                None
            });
            Ok(match group(stmt, children, Op2::Union, ctx)? {
                Geom::Solid(s) => Geom::Solid(match color {
                    Some(c) => s.color(c),
                    None => s,
                }),
                other => other,
            })
        }
        "difference" => group(stmt, children, Op2::Difference, ctx),
        "intersection" => group(stmt, children, Op2::Intersection, ctx),
        "multmatrix" => {
            if non_finite(stmt) {
                ctx.warn(
                    stmt,
                    "the transformation matrix contains nan or inf: the object is removed",
                );
                return Ok(Geom::Empty);
            }
            let m = matrix(stmt)?;
            Ok(match group(stmt, children, Op2::Union, ctx)? {
                Geom::Solid(s) if is_identity(&m) => Geom::Solid(s),
                Geom::Solid(s) => Geom::Solid(s.affine(m)),
                Geom::Flat(mut f) => {
                    f.transform([[m[0][0], m[0][1], m[0][3]], [m[1][0], m[1][1], m[1][3]]]);
                    Geom::Flat(f)
                }
                Geom::Empty => Geom::Empty,
            })
        }
        "sphere" => {
            let r = radius(stmt, "r", "d", 0, 1.0)?;
            if r <= 0.0 {
                return leaf(Geom::Empty);
            }
            let s = if faceted {
                let (v, f) = facets::sphere(r, stmt.resolution()?);
                faceted_solid(stmt, v, f)?
            } else {
                Solid::sphere(r)
            };
            leaf(Geom::Solid(s))
        }
        "cube" => {
            let size = stmt.size3("size", Some(0), 1.0)?;
            if size.min_element() <= 0.0 {
                return leaf(Geom::Empty);
            }
            let c = Solid::cuboid(size);
            let centred = stmt.flag("center", Some(1), false)?;
            leaf(Geom::Solid(if centred {
                c
            } else {
                c.translate(size / 2.0)
            }))
        }
        "cylinder" => cylinder(stmt, faceted).and_then(leaf),
        "polyhedron" => {
            // OpenSCAD reports points that are not 3-vectors and skips the polyhedron.
            let points = match stmt.points("points", Some(0), 3) {
                Ok(p) => p,
                Err(CsgError::Argument { message, .. }) => {
                    ctx.warn(stmt, format!("{message}: the object is skipped"));
                    return Ok(Geom::Empty);
                }
                Err(e) => return Err(e),
            };
            let faces = match stmt.index_lists("faces", Some(1))? {
                Some(f) => f,
                None => match stmt.index_lists("triangles", None)? {
                    Some(f) => f,
                    None => {
                        // OpenSCAD renders a polyhedron without faces as nothing.
                        ctx.warn(stmt, "'faces' is undef: the object is skipped");
                        return Ok(Geom::Empty);
                    }
                },
            };
            // OpenSCAD lists faces clockwise seen from outside; the kernel counter-clockwise.
            let faces = faces
                .into_iter()
                .map(|f| f.into_iter().rev().collect())
                .collect();
            let (faces, cleaned) = super::faces::clean_faces(&points, faces);
            if let Some(message) = cleaned.message() {
                ctx.warn(stmt, message);
            }
            if faces.is_empty() {
                ctx.warn(
                    stmt,
                    "polyhedron: no face encloses anything: the object is empty",
                );
                return leaf(Geom::Empty);
            }
            leaf(Geom::Solid(polyhedron(stmt, points, faces)?))
        }
        "circle" => {
            let r = radius(stmt, "r", "d", 0, 1.0)?;
            let res = stmt.resolution()?;
            leaf(if r <= 0.0 {
                Geom::Empty
            } else {
                Geom::Flat(Flat::leaf(Leaf2::Circle {
                    center: DVec2::ZERO,
                    radius: r,
                    res,
                }))
            })
        }
        "square" => {
            let s = stmt.size2("size", Some(0), 1.0)?;
            if s.min_element() <= 0.0 {
                return leaf(Geom::Empty);
            }
            let o = if stmt.flag("center", Some(1), false)? {
                -s / 2.0
            } else {
                DVec2::ZERO
            };
            let pts = [DVec2::ZERO, DVec2::new(s.x, 0.0), s, DVec2::new(0.0, s.y)];
            leaf(Geom::Flat(Flat::leaf(Leaf2::Polygon(vec![
                pts.map(|p| p + o).to_vec(),
            ]))))
        }
        "polygon" => {
            let points: Vec<DVec2> = stmt
                .points("points", Some(0), 2)?
                .iter()
                .map(|p| p.truncate())
                .collect();
            let paths = stmt
                .index_lists("paths", Some(1))?
                .unwrap_or_else(|| vec![(0..points.len() as u32).collect()]);
            let mut loops = Vec::new();
            for path in paths {
                let l = path
                    .iter()
                    .map(|&k| points.get(k as usize).copied())
                    .collect::<Option<Vec<_>>>()
                    .ok_or_else(|| stmt.error("'paths': index out of range"))?;
                loops.push(l);
            }
            if loops.iter().all(|l| l.len() < 3) {
                return leaf(Geom::Empty);
            }
            leaf(Geom::Flat(Flat::leaf(Leaf2::Polygon(loops))))
        }
        "linear_extrude" => {
            let Some(flat) = flat_children(stmt, children, ctx) else {
                return Ok(Geom::Empty);
            };
            let h = stmt.num("height", Some(0), 100.0)?;
            if h <= 0.0 {
                // OpenSCAD makes nothing of a height of zero or less.
                ctx.warn(
                    stmt,
                    format!("height = {h} is not positive: the object is empty"),
                );
                return Ok(Geom::Empty);
            }
            let twist = stmt.num("twist", None, 0.0)?;
            let scale = stmt.size2("scale", None, 1.0)?;
            let centred = stmt.flag("center", None, false)?;
            let exact = |p| {
                Extrude::with_scale(p, h, -twist, scale).map(|e| Primitive::Extrude(Arc::new(e)))
            };
            // With OpenSCAD's facets a twisted or unevenly scaled extrusion is OpenSCAD's stack
            // of flat slices (`sliced.rs`); otherwise (and where the stack is refused) the exact
            // sweep, whose flat walls are the same.
            let s = if faceted
                && (twist != 0.0 || scale.x != scale.y)
                && flat.leaf_count() <= sliced::MAX_SLICED_LEAVES
            {
                // OpenSCAD reads a slice count that is not a finite number as none.
                let given = match stmt.arg("slices", None) {
                    Some(Value::Num(n)) if n.is_finite() => Some(*n),
                    _ => None,
                };
                let reach = reach(stmt, &flat, faceted, scale)?;
                let slices = sliced::slice_count(given, h, twist, scale, stmt.resolution()?, reach);
                let too_many = std::cell::Cell::new(false);
                let s = sweep_solid(stmt, &flat, faceted, |p| {
                    let loops = p.outline(0);
                    let corners = loops.iter().map(Vec::len).sum::<usize>() as f64;
                    let small = (slices + 1.0) * corners <= sliced::MAX_SLICE_CORNERS as f64;
                    too_many.set(too_many.get() || !small);
                    let stack = small
                        .then(|| sliced::sliced_extrusion(&loops, h, twist, scale, slices as usize))
                        .flatten();
                    match stack {
                        Some((v, f)) => polyhedron(stmt, v, f),
                        None => exact(p)
                            .map(Solid::primitive)
                            .map_err(|e| stmt.error(e.to_string())),
                    }
                })?;
                if too_many.get() {
                    ctx.warn(
                        stmt,
                        format!(
                            "{slices} slices would need more than {} vertices: meshed as the \
                             exact twisted solid instead of OpenSCAD's flat slices",
                            sliced::MAX_SLICE_CORNERS
                        ),
                    );
                }
                s
            } else {
                sweep(stmt, &flat, faceted, exact)?
            };
            Ok(Geom::Solid(if centred {
                s
            } else {
                s.translate(DVec3::new(0.0, 0.0, h / 2.0))
            }))
        }
        "rotate_extrude" => {
            let Some(flat) = flat_children(stmt, children, ctx) else {
                return Ok(Geom::Empty);
            };
            // As in OpenSCAD: at most a full turn either way; a negative angle sweeps clockwise
            // (the mirror image in y of the counter-clockwise sweep).
            let angle = stmt.num("angle", None, 360.0)?.clamp(-360.0, 360.0);
            if angle == 0.0 {
                // OpenSCAD sweeps nothing.
                ctx.warn(stmt, "angle = 0: the object is empty");
                return Ok(Geom::Empty);
            }
            // OpenSCAD's rule: the profile lies on one side of the axis. A profile at x ≤ 0 is
            // swept as its mirror image (x ↦ -x), turned half a turn about z: a point at -x
            // turned by θ lies where the point at x turned by θ + 180° does.
            let (lo, hi) = x_range(stmt, &flat, faceted)?;
            if lo < 0.0 && hi > 0.0 {
                ctx.warn(
                    stmt,
                    format!(
                        "all points for rotate_extrude() must have the same X coordinate sign \
                         (range is {lo:.2} -> {hi:.2}): the object is skipped"
                    ),
                );
                return Ok(Geom::Empty);
            }
            let mirrored = lo < 0.0;
            let mut flat = flat;
            if mirrored {
                flat.transform([[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
            }
            // With OpenSCAD's facets a full turn is its straight steps: as many as a circle of
            // radius max |x| gets, the first stop on the -x axis (OpenSCAD's "legacy" start;
            // the mirrored case is turned below, as OpenSCAD's rings are). Partial turns stay
            // smooth.
            let steps = (faceted && angle.abs() == 360.0)
                .then(|| stmt.resolution())
                .transpose()?
                .map(|res| facets::fragments(hi.max(0.0) - lo.min(0.0), res) as u32);
            // A partial turn under OpenSCAD's facets is its straight steps too, from +x
            // (`turned.rs`), for profiles of a few 2D leaves (each leaf is a mesh solid).
            let partial =
                (faceted && angle.abs() < 360.0 && flat.leaf_count() <= sliced::MAX_SLICED_LEAVES)
                    .then(|| stmt.resolution())
                    .transpose()?
                    .map(|res| {
                        let fragments = facets::fragments(hi.max(0.0) - lo.min(0.0), res);
                        turned::step_count(fragments, angle)
                    });
            let mut s = sweep_solid(stmt, &flat, faceted, |p| {
                if let Some(steps) = partial
                    && let Some((v, f)) = turned::stepped_turn(&p.outline(0), angle.abs(), steps)
                {
                    return polyhedron(stmt, v, f);
                }
                match steps {
                    Some(n) => Revolve::faceted(p, n, 180.0),
                    None => Revolve::new(p, angle.abs()),
                }
                .map(|r| Solid::primitive(Primitive::Revolve(Arc::new(r))))
                .map_err(|e| stmt.error(e.to_string()))
            })?;
            if mirrored {
                s = s.rotate(DVec3::Z, 180.0);
            }
            Ok(Geom::Solid(if angle < 0.0 {
                s.scale(DVec3::new(1.0, -1.0, 1.0))
            } else {
                s
            }))
        }
        "import" => {
            let mut found = Vec::new();
            let got = import(stmt, ctx.files, &mut |m| found.push(m))?;
            for m in found {
                ctx.warn(stmt, m);
            }
            leaf(match got {
                Imported::Solid(s) => Geom::Solid(s),
                Imported::Flat(f) => f.map_or(Geom::Empty, Geom::Flat),
            })
        }
        "surface" => {
            let path = string_arg(stmt, "file", Some(0))
                .filter(|p| !p.is_empty())
                .ok_or_else(|| stmt.error("'file': expected a file name"))?;
            let bytes = ctx
                .files
                .read_file(path)
                .map_err(|e| stmt.error(e.to_string()))?;
            match surface(stmt, path, &bytes)? {
                Some(s) => leaf(Geom::Solid(s)),
                None => {
                    ctx.warn(stmt, format!("{path}: fewer than 2 × 2 heights: empty"));
                    leaf(Geom::Empty)
                }
            }
        }
        "text" => leaf(text(stmt, &mut ctx.texts)?.map_or(Geom::Empty, Geom::Flat)),
        "projection" => {
            let mut solids = Vec::new();
            let mut ignored = false;
            for c in children {
                match c {
                    Geom::Solid(s) => solids.push(s),
                    Geom::Flat(_) => ignored = true,
                    Geom::Empty => {}
                }
            }
            if ignored {
                ctx.warn(stmt, "ignoring 2D child object for projection");
            }
            if solids.is_empty() {
                return Ok(Geom::Empty);
            }
            let s = if solids.len() == 1 {
                solids.remove(0)
            } else {
                Solid::union_all(solids)
            };
            Ok(projection(stmt, &s)?.map_or(Geom::Empty, Geom::Flat))
        }
        "resize" => {
            let geom = group(stmt, children, Op2::Union, ctx)?;
            resize(stmt, geom, faceted, ctx)
        }
        "offset" => {
            let how = if stmt.arg("r", None).is_some() {
                Offset::Round {
                    r: stmt.num("r", None, 1.0)?,
                    res: stmt.resolution()?,
                }
            } else {
                Offset::Delta {
                    delta: stmt.num("delta", None, 1.0)?,
                    chamfer: stmt.flag("chamfer", None, false)?,
                }
            };
            let Some(flat) = flat_children(stmt, children, ctx) else {
                return Ok(Geom::Empty);
            };
            Ok(offset(flat, how)
                .map_err(|e| stmt.error(e))?
                .map_or(Geom::Empty, Geom::Flat))
        }
        other => Err(CsgError::Unsupported {
            pos: stmt.pos,
            name: other.to_string(),
        }),
    }
}

/// Replays a 2D program in 3D: each leaf swept by `make`.
pub(super) fn sweep<E: std::fmt::Display>(
    stmt: &Stmt,
    flat: &Flat,
    faceted: bool,
    make: impl Fn(solidkit_kernel::profile::Profile) -> Result<Primitive, E>,
) -> Result<Solid, CsgError> {
    sweep_solid(stmt, flat, faceted, |p| {
        make(p)
            .map(Solid::primitive)
            .map_err(|e| stmt.error(e.to_string()))
    })
}

/// [`sweep`] with a maker of whole solids (a primitive or a polyhedron per leaf).
fn sweep_solid(
    stmt: &Stmt,
    flat: &Flat,
    faceted: bool,
    make: impl Fn(solidkit_kernel::profile::Profile) -> Result<Solid, CsgError>,
) -> Result<Solid, CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            make(p)
        },
        |op, mut parts| match op {
            Op2::Difference(_) => {
                let base = parts.remove(0);
                Solid::difference_all(base, parts)
            }
            Op2::Intersection(_) => Solid::intersection_all(parts),
            _ => Solid::union_all(parts),
        },
    )
}

/// The range of x a 2D geometry can reach: its leaves' profile bounds, combined by its Booleans
/// (a difference within its first operand, an intersection within every operand).
fn x_range(stmt: &Stmt, flat: &Flat, faceted: bool) -> Result<(f64, f64), CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            let (lo, hi) = p.bounds();
            Ok((lo.x, hi.x))
        },
        |op, parts| match op {
            Op2::Difference(_) => parts[0],
            Op2::Intersection(_) => parts
                .into_iter()
                .fold((f64::NEG_INFINITY, f64::INFINITY), |a, b| {
                    (a.0.max(b.0), a.1.min(b.1))
                }),
            _ => parts
                .into_iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |a, b| {
                    (a.0.min(b.0), a.1.max(b.1))
                }),
        },
    )
}

/// How far a 2D geometry's corners reach ([`sliced::Reach`]), combined by its Booleans as
/// [`x_range`] combines ranges: the corners of a difference are within its first operand's,
/// an intersection's within the closest operand's.
fn reach(stmt: &Stmt, flat: &Flat, faceted: bool, scale: DVec2) -> Result<sliced::Reach, CsgError> {
    flat.evaluate(
        |leaf| {
            let p = profile(leaf, faceted).map_err(|e| stmt.error(format!("profile: {e}")))?;
            Ok(sliced::Reach::of(&p.outline(0), scale))
        },
        |op, parts| {
            let pick = |f: fn(f64, f64) -> f64, start: f64| sliced::Reach {
                r_sqr: parts.iter().map(|r| r.r_sqr).fold(start, f),
                delta_sqr: parts.iter().map(|r| r.delta_sqr).fold(start, f),
            };
            match op {
                Op2::Difference(_) => parts[0],
                Op2::Intersection(_) => pick(f64::min, f64::INFINITY),
                _ => pick(f64::max, 0.0),
            }
        },
    )
}

/// A polyhedral solid, errors located at `stmt`.
fn polyhedron(stmt: &Stmt, v: Vec<DVec3>, f: Vec<Vec<u32>>) -> Result<Solid, CsgError> {
    Solid::polyhedron(v, f).map_err(|e| stmt.error(e.to_string()))
}

/// OpenSCAD's faceting of a round primitive: a convex polyhedron of face planes
/// ([`super::convex`]), or a mesh solid where a face is degenerate.
fn faceted_solid(stmt: &Stmt, v: Vec<DVec3>, f: Vec<Vec<u32>>) -> Result<Solid, CsgError> {
    match super::convex::convex_polyhedron(&v, &f) {
        Some(s) => Ok(s),
        None => polyhedron(stmt, v, f),
    }
}

/// A radius given as `r` or as diameter `d`.
fn radius(stmt: &Stmt, r: &str, d: &str, position: usize, default: f64) -> Result<f64, CsgError> {
    if stmt.arg(d, None).is_some() {
        return Ok(stmt.num(d, None, 0.0)? / 2.0);
    }
    stmt.num(r, Some(position), default)
}

/// `cylinder(h, r1, r2, center)` (also `r`, `d`, `d1`, `d2`): exact cylinder or cone, or
/// OpenSCAD's faceted one.
fn cylinder(stmt: &Stmt, faceted: bool) -> Result<Geom, CsgError> {
    let Some((r1, r2, z0, h)) = cylinder_params(stmt)? else {
        return Ok(Geom::Empty);
    };
    let s = if faceted {
        let (v, f) = facets::cylinder(r1, r2, z0, z0 + h, stmt.resolution()?);
        faceted_solid(stmt, v, f)?
    } else {
        let c = if r1 == r2 {
            Solid::cylinder(r1, h)
        } else {
            Solid::cone(r1, r2, h)
        };
        let mid = z0 + h / 2.0;
        if mid == 0.0 {
            c
        } else {
            c.translate(DVec3::new(0.0, 0.0, mid))
        }
    };
    Ok(Geom::Solid(s))
}

/// A cylinder's `(r1, r2, z0, h)`, or `None` when it is empty.
fn cylinder_params(stmt: &Stmt) -> Result<Option<(f64, f64, f64, f64)>, CsgError> {
    let h = stmt.num("h", Some(0), 1.0)?;
    let r = radius(stmt, "r", "d", usize::MAX, 1.0)?;
    let r1 = if stmt.arg("d1", None).is_some() {
        stmt.num("d1", None, 0.0)? / 2.0
    } else {
        stmt.num("r1", Some(1), r)?
    };
    let r2 = if stmt.arg("d2", None).is_some() {
        stmt.num("d2", None, 0.0)? / 2.0
    } else {
        stmt.num("r2", Some(2), r)?
    };
    let centred = stmt.flag("center", Some(3), false)?;
    if h <= 0.0 || r1 < 0.0 || r2 < 0.0 || (r1 == 0.0 && r2 == 0.0) {
        return Ok(None);
    }
    Ok(Some((r1, r2, if centred { -h / 2.0 } else { 0.0 }, h)))
}

/// `multmatrix(m)`: 4 rows (the last `[0, 0, 0, 1]`) or 3 rows of 4 numbers.
fn matrix(stmt: &Stmt) -> Result<[[f64; 4]; 3], CsgError> {
    let bad = || stmt.error("'m': expected a 4 × 4 affine matrix");
    let Some(Value::Vector(rows)) = stmt.arg("m", Some(0)) else {
        return Err(bad());
    };
    let rows: Vec<Vec<f64>> = rows
        .iter()
        .map(numbers)
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    if !(rows.len() == 3 || rows.len() == 4) || rows.iter().any(|r| r.len() != 4) {
        return Err(bad());
    }
    if rows.len() == 4 && rows[3] != [0.0, 0.0, 0.0, 1.0] {
        return Err(stmt.error("'m': projective matrices are not supported"));
    }
    Ok([0, 1, 2].map(|i| [rows[i][0], rows[i][1], rows[i][2], rows[i][3]]))
}

fn is_identity(m: &[[f64; 4]; 3]) -> bool {
    (0..3).all(|i| (0..4).all(|j| m[i][j] == if i == j { 1.0 } else { 0.0 }))
}

/// Cells along the longest side of the grid on which `hull()` and `minkowski()` mesh an operand
/// whose points are not known exactly (a `difference`, an extrusion, …).
const OPERAND_RESOLUTION: usize = 128;

/// What `hull()` / `minkowski()` know about a statement under them, from its own arguments or its
/// children's; `None` when only its geometry can tell (then it is meshed).
fn hullable_of(
    stmt: &Stmt,
    geom: &Geom,
    infos: Vec<Option<Hullable>>,
) -> Result<Option<Hullable>, CsgError> {
    let convex = |points: Vec<DVec3>| {
        let pieces = Some(if points.is_empty() {
            Vec::new()
        } else {
            vec![points.clone()]
        });
        Some(Hullable {
            points,
            convex: true,
            pieces,
        })
    };
    if matches!(geom, Geom::Empty) {
        return Ok(convex(Vec::new()));
    }
    Ok(match stmt.name.as_str() {
        "sphere" | "cylinder" | "cube" => convex(primitive_points(stmt)?),
        "circle" | "square" => Some(Hullable {
            points: flat_points(geom).unwrap_or_default(),
            convex: true,
            pieces: None,
        }),
        "polygon" => {
            let Geom::Flat(f) = geom else { return Ok(None) };
            let points = flat_points(geom).unwrap_or_default();
            let ring: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
            let single = matches!(&f.0[..], [Op2::Leaf(Leaf2::Polygon(loops))] if loops.len() == 1);
            let hull_area = area2(&convex_hull_2d(&ring)).abs();
            let is_convex = single && (area2(&ring).abs() - hull_area).abs() <= 1e-9 * hull_area;
            Some(Hullable {
                points,
                convex: is_convex,
                pieces: None,
            })
        }
        "polyhedron" => {
            let points = stmt.points("points", Some(0), 3)?;
            let volume = polyhedron_volume(stmt, &points)?;
            let hull_volume = convex_hull(&points)
                .and_then(|(v, f)| Polyhedron::new(v, f).ok())
                .map(|p| p.volume());
            let is_convex = matches!((volume, hull_volume), (Some(a), Some(b)) if (a - b).abs() <= 1e-9 * b.abs());
            let pieces = is_convex.then(|| vec![points.clone()]);
            Some(Hullable {
                points,
                convex: is_convex,
                pieces,
            })
        }
        "group" | "union" | "color" | "render" | "multmatrix" => {
            let Some(infos) = infos.into_iter().collect::<Option<Vec<Hullable>>>() else {
                return Ok(None);
            };
            let non_empty: Vec<&Hullable> = infos.iter().filter(|h| !h.points.is_empty()).collect();
            let is_convex = non_empty.len() == 1 && non_empty[0].convex;
            let mut points: Vec<DVec3> = infos
                .iter()
                .flat_map(|h| h.points.iter().copied())
                .collect();
            let mut pieces = infos
                .into_iter()
                .try_fold(Vec::new(), |acc, h| pieces::union(acc, h.pieces?));
            if stmt.name == "multmatrix" {
                let m = matrix(stmt)?;
                for p in points
                    .iter_mut()
                    .chain(pieces.iter_mut().flatten().flatten())
                {
                    *p = apply(&m, *p);
                }
            }
            Some(Hullable {
                points,
                convex: is_convex,
                pieces,
            })
        }
        "difference" | "intersection" if matches!(geom, Geom::Solid(_)) => {
            // Known exactly where every operand is made of convex pieces; meshed otherwise.
            let Some(infos) = infos.into_iter().collect::<Option<Vec<Hullable>>>() else {
                return Ok(None);
            };
            let Some(sets) = infos
                .into_iter()
                .map(|h| h.pieces)
                .collect::<Option<Vec<Vec<Piece>>>>()
            else {
                return Ok(None);
            };
            let mut sets = sets.into_iter();
            let first = sets.next().unwrap_or_default();
            let pieces = if stmt.name == "difference" {
                sets.try_fold(first, |acc, b| pieces::difference(acc, &b))
            } else {
                sets.try_fold(first, |acc, b| pieces::intersection(&acc, &b))
            };
            let Some(pieces) = pieces else {
                return Ok(None);
            };
            Some(Hullable {
                points: pieces.iter().flatten().copied().collect(),
                convex: pieces.len() == 1,
                pieces: Some(pieces),
            })
        }
        _ => None,
    })
}

/// The volume of a `polyhedron` statement (faces fanned; orientation ignored).
fn polyhedron_volume(stmt: &Stmt, points: &[DVec3]) -> Result<Option<f64>, CsgError> {
    let faces = match stmt.index_lists("faces", Some(1))? {
        Some(f) => f,
        None => match stmt.index_lists("triangles", None)? {
            Some(f) => f,
            None => return Ok(None),
        },
    };
    let mut six = 0.0;
    for f in &faces {
        let Some(p) = f
            .iter()
            .map(|&k| points.get(k as usize).copied())
            .collect::<Option<Vec<DVec3>>>()
        else {
            return Ok(None);
        };
        for k in 1..p.len().saturating_sub(1) {
            six += p[0].dot(p[k].cross(p[k + 1]));
        }
    }
    Ok(Some(six.abs() / 6.0))
}

/// `m·p` for a 3 × 4 affine matrix.
fn apply(m: &[[f64; 4]; 3], p: DVec3) -> DVec3 {
    DVec3::from_array([0, 1, 2].map(|r| m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3]))
}

/// Signed area of a loop (shoelace).
fn area2(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum::<f64>()
        / 2.0
}

/// The points of a 2D region made of leaves and unions only (circles faceted the OpenSCAD way),
/// at z = 0; `None` when it has a difference or intersection.
fn flat_points(geom: &Geom) -> Option<Vec<DVec3>> {
    let Geom::Flat(f) = geom else { return None };
    let mut out = Vec::new();
    for op in &f.0 {
        match op {
            Op2::Leaf(Leaf2::Circle {
                center,
                radius,
                res,
            }) => out.extend(
                facets::circle(*radius, facets::fragments(*radius, *res))
                    .into_iter()
                    .map(|p| (p + *center).extend(0.0)),
            ),
            Op2::Leaf(Leaf2::Polygon(loops)) => {
                out.extend(loops.iter().flatten().map(|p| p.extend(0.0)))
            }
            Op2::Union(_) => {}
            Op2::Difference(_) | Op2::Intersection(_) => return None,
        }
    }
    Some(out)
}

/// Points whose convex hull is the hull of `geom`, when they are not known exactly: the vertices
/// of its marching-cubes mesh ([`OPERAND_RESOLUTION`] cells along the longest side; 2D regions
/// are extruded to a unit slab, meshed and flattened).
fn geometry_points(stmt: &Stmt, geom: &Geom) -> Result<Vec<DVec3>, CsgError> {
    if let Some(points) = flat_points(geom) {
        return Ok(points);
    }
    let points = meshed_points(stmt, geom, OPERAND_RESOLUTION)?;
    if points.is_empty() {
        return Ok(points);
    }
    // Reduce to the vertices of their hull, within a fraction of a cell.
    let (lo, hi) = points.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let cell = (hi - lo).max_element() / OPERAND_RESOLUTION as f64;
    if matches!(geom, Geom::Flat(_)) {
        return Ok(points);
    }
    let eps = OPERAND_HULL_CELLS * cell;
    // Akl–Toussaint: the hull of the extreme points along a few hundred directions, and only
    // the points outside it, go to the incremental hull (whose cost grows with points × faces).
    let n = 256;
    let mut extreme: Vec<DVec3> = (0..n)
        .map(|k| {
            let z = 1.0 - (2 * k + 1) as f64 / n as f64;
            let phi = k as f64 * std::f64::consts::PI * (3.0 - 5f64.sqrt());
            let r = (1.0 - z * z).sqrt();
            let d = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            points
                .iter()
                .copied()
                .max_by(|a, b| d.dot(*a).total_cmp(&d.dot(*b)))
                .expect("points")
        })
        .collect();
    let Some((v, f)) = convex_hull_within(&extreme, eps) else {
        return Ok(points);
    };
    let planes: Vec<(DVec3, f64)> = f
        .iter()
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|i| v[t[i] as usize]);
            let n = (b - a).cross(c - a).normalize_or_zero();
            (n, n.dot(a))
        })
        .collect();
    extreme.extend(
        points
            .iter()
            .filter(|p| planes.iter().any(|(n, d)| n.dot(**p) - d > eps)),
    );
    Ok(match convex_hull_within(&extreme, eps) {
        Some((v, _)) => v,
        None => points,
    })
}

/// The vertices of a marching-cubes mesh of `geom` with `resolution` cells along the longest
/// side (2D regions extruded to a unit slab and flattened).
pub(super) fn meshed_points(
    stmt: &Stmt,
    geom: &Geom,
    resolution: usize,
) -> Result<Vec<DVec3>, CsgError> {
    let (solid, flatten) = match geom {
        Geom::Empty => return Ok(Vec::new()),
        Geom::Solid(s) => (s.clone(), false),
        Geom::Flat(f) => (
            sweep(stmt, f, true, |p| {
                Extrude::new(p, 1.0, 0.0, 1.0).map(|e| Primitive::Extrude(Arc::new(e)))
            })?,
            true,
        ),
    };
    let mut points = mesh_of(stmt, &solid, resolution)?.positions;
    if flatten {
        for p in &mut points {
            p.z = 0.0;
        }
    }
    Ok(points)
}

/// A marching-cubes mesh of `solid` with `resolution` cells along the longest side of its box
/// (empty for an empty solid); errors located at `stmt`.
pub(super) fn mesh_of(
    stmt: &Stmt,
    solid: &Solid,
    resolution: usize,
) -> Result<IndexedMesh, CsgError> {
    solid.validate().map_err(|e| stmt.error(e.to_string()))?;
    let bounds = solid.bbox();
    // A box without volume (operands that only touch) holds no solid.
    if bounds.is_empty() || (bounds.max - bounds.min).min_element() <= 0.0 {
        return Ok(IndexedMesh::default());
    }
    let spec = GridSpec::for_bounds(&bounds, resolution)
        .map_err(|e| stmt.error(format!("meshing an operand: {e}")))?;
    let (mesh, _) = mesh_sparse(&solid.compile(), spec, &SparseOptions::default())
        .map_err(|e| stmt.error(format!("meshing an operand: {e}")))?;
    Ok(mesh)
}

/// An operand of `hull()` / `minkowski()`: its geometry, points, and index among the kept
/// children.
type Operand = (Geom, Hullable, usize);

/// The non-empty operands of `hull()` / `minkowski()` with their points (known or meshed), all
/// of the first operand's dimension (others are ignored with a warning, as OpenSCAD does).
fn operands(
    stmt: &Stmt,
    children: Vec<Geom>,
    infos: Vec<Option<Hullable>>,
    ctx: &mut Ctx,
) -> Result<(Option<u8>, Vec<Operand>), CsgError> {
    let mut dim = None;
    let mut ignored = false;
    let mut out = Vec::new();
    for (k, (g, info)) in children.into_iter().zip(infos).enumerate() {
        let d = match &g {
            Geom::Empty => continue,
            Geom::Solid(_) => 3,
            Geom::Flat(_) => 2,
        };
        if dim.is_some_and(|x| x != d) {
            ignored = true;
            continue;
        }
        dim = Some(d);
        let info = match info {
            Some(h) => h,
            None => Hullable {
                points: geometry_points(stmt, &g)?,
                convex: false,
                pieces: None,
            },
        };
        out.push((g, info, k));
    }
    if ignored {
        ctx.warn(
            stmt,
            "mixing 2D and 3D objects is not supported: the children of the other dimension than the first are ignored",
        );
    }
    Ok((dim, out))
}

/// The convex hull of `points` as geometry of dimension `dim` (empty when degenerate), with its
/// vertices.
fn hull_of(stmt: &Stmt, dim: u8, points: &[DVec3]) -> Result<(Geom, Option<Hullable>), CsgError> {
    if dim == 2 {
        let flat: Vec<DVec2> = points.iter().map(|p| p.truncate()).collect();
        let ring = convex_hull_2d(&flat);
        if ring.len() < 3 {
            return Ok((Geom::Empty, None));
        }
        let points = ring.iter().map(|p| p.extend(0.0)).collect();
        return Ok((
            Geom::Flat(Flat::leaf(Leaf2::Polygon(vec![ring]))),
            Some(Hullable {
                points,
                convex: true,
                pieces: None,
            }),
        ));
    }
    let Some((v, f)) = convex_hull(points) else {
        return Ok((Geom::Empty, None));
    };
    let info = Hullable {
        points: v.clone(),
        convex: true,
        pieces: Some(vec![v.clone()]),
    };
    // A hull is convex: the intersection of its face planes evaluates in a dot product per face
    // and prunes per octree cell, where a mesh solid pays a winding number per sample.
    Ok((Geom::Solid(faceted_solid(stmt, v, f)?), Some(info)))
}

/// `hull()` of any children: the convex hull of their points (exact for primitives, polyhedra,
/// polygons, their unions, transforms, and the differences and intersections of convex parts; the
/// vertices of a fine mesh otherwise).
fn hull(
    stmt: &Stmt,
    children: Vec<Geom>,
    infos: Vec<Option<Hullable>>,
    ctx: &mut Ctx,
) -> Result<(Geom, Option<Hullable>), CsgError> {
    let (dim, ops) = operands(stmt, children, infos, ctx)?;
    let Some(dim) = dim else {
        return Ok((Geom::Empty, None));
    };
    let points: Vec<DVec3> = ops.into_iter().flat_map(|(_, h, _)| h.points).collect();
    hull_of(stmt, dim, &points)
}

/// The radius and centre of a sphere operand of `minkowski()`: a `sphere` under groups and
/// translations only.
fn sphere_operand(tree: &Tree, mut k: usize) -> Result<Option<(f64, DVec3)>, CsgError> {
    let mut t = DVec3::ZERO;
    loop {
        let s = &tree.nodes[k];
        let kids: Vec<usize> = s
            .children
            .iter()
            .copied()
            .filter(|&c| !tree.nodes[c].modifiers.dropped())
            .collect();
        match s.name.as_str() {
            "sphere" => {
                let r = radius(s, "r", "d", 0, 1.0)?;
                return Ok((r > 0.0).then_some((r, t)));
            }
            "group" | "union" | "color" | "render" if kids.len() == 1 => k = kids[0],
            "multmatrix" if kids.len() == 1 => {
                let m = matrix(s)?;
                if (0..3).any(|i| (0..3).any(|j| m[i][j] != if i == j { 1.0 } else { 0.0 })) {
                    return Ok(None);
                }
                t += DVec3::new(m[0][3], m[1][3], m[2][3]);
                k = kids[0];
            }
            _ => return Ok(None),
        }
    }
}

/// `minkowski()`: of convex operands, the hull of the sums of their points (exact: the sum of
/// convex sets is the hull of the sums of their vertices); with a sphere operand and exact
/// facets, or with one non-convex operand and a sphere, an offset of the other operand by the
/// sphere's radius. Anything else is refused.
fn minkowski(
    tree: &Tree,
    kids: &[usize],
    stmt: &Stmt,
    children: Vec<Geom>,
    infos: Vec<Option<Hullable>>,
    ctx: &mut Ctx,
) -> Result<(Geom, Option<Hullable>), CsgError> {
    let (dim, mut ops) = operands(stmt, children, infos, ctx)?;
    let Some(dim) = dim else {
        return Ok((Geom::Empty, None));
    };
    if ops.len() == 1 {
        let (g, h, _) = ops.pop().expect("one operand");
        return Ok((g, Some(h)));
    }
    let all_convex = ops.iter().all(|(_, h, _)| h.convex);
    let mut spheres = Vec::new();
    if dim == 3 && (ctx.facets == Facets::Exact || !all_convex) {
        for (n, (_, _, k)) in ops.iter().enumerate() {
            if let Some(s) = sphere_operand(tree, kids[*k])? {
                spheres.push((n, s));
            }
        }
    }
    if spheres.is_empty() || spheres.len() == ops.len() {
        if !all_convex
            && dim == 3
            && let Some(g) = minkowski_by_pieces(stmt, &ops)?
        {
            return Ok((g, None));
        }
        if !all_convex {
            return Err(stmt.error(
                "only convex operands (primitives, convex polyhedra and polygons, hulls, and \
                 their transforms), one operand cut into at most 512 convex pieces (unions, \
                 differences and intersections of convex parts of up to 130 faces) with convex \
                 others, or a sphere with any other operand, are supported",
            ));
        }
        let sum = minkowski_points(dim, ops.into_iter().map(|(_, h, _)| h.points));
        return hull_of(stmt, dim, &sum);
    }
    // Offset the rest by the spheres (their sum is one sphere).
    let (r, t) = spheres
        .iter()
        .fold((0.0, DVec3::ZERO), |(r, t), (_, (sr, st))| {
            (r + sr, t + *st)
        });
    for (n, _) in spheres.iter().rev() {
        ops.remove(*n);
    }
    let rest = if ops.len() == 1 {
        ops.pop().expect("one operand").0
    } else if ops.iter().all(|(_, h, _)| h.convex) {
        let sum = minkowski_points(dim, ops.into_iter().map(|(_, h, _)| h.points));
        hull_of(stmt, dim, &sum)?.0
    } else {
        return Err(
            stmt.error("more than one non-convex operand besides the sphere is not supported")
        );
    };
    let Geom::Solid(s) = rest else {
        return Ok((Geom::Empty, None));
    };
    if ctx.facets == Facets::OpenScad {
        ctx.warn(
            stmt,
            "minkowski with a non-convex operand: the sphere operand is taken as exact (an offset)",
        );
    }
    let s = s.offset(r);
    Ok((
        Geom::Solid(if t == DVec3::ZERO { s } else { s.translate(t) }),
        None,
    ))
}

/// `minkowski()` of one operand made of convex pieces ([`super::pieces`]) and convex others: the
/// union of the hulls of each piece plus the others' sum; `None` when an operand is neither.
fn minkowski_by_pieces(stmt: &Stmt, ops: &[Operand]) -> Result<Option<Geom>, CsgError> {
    let (rest, convex): (Vec<&Operand>, Vec<&Operand>) =
        ops.iter().partition(|(_, h, _)| !h.convex);
    let [(_, decomposed, _)] = rest[..] else {
        return Ok(None);
    };
    let Some(parts) = &decomposed.pieces else {
        return Ok(None);
    };
    let b = minkowski_points(3, convex.iter().map(|(_, h, _)| h.points.clone()));
    let mut solids = Vec::new();
    for sum in pieces::sum_with_convex(parts, &b) {
        if let (Geom::Solid(s), _) = hull_of(stmt, 3, &sum)? {
            solids.push(s);
        }
    }
    Ok(Some(if solids.is_empty() {
        Geom::Empty
    } else {
        Geom::Solid(Solid::union_all(solids))
    }))
}

/// The vertices of the Minkowski sum of the convex hulls of `sets` (reduced to hull vertices
/// after each step).
fn minkowski_points(dim: u8, sets: impl Iterator<Item = Vec<DVec3>>) -> Vec<DVec3> {
    let reduce = |p: Vec<DVec3>| -> Vec<DVec3> {
        if dim == 2 {
            let flat: Vec<DVec2> = p.iter().map(|q| q.truncate()).collect();
            let ring = convex_hull_2d(&flat);
            return ring.into_iter().map(|q| q.extend(0.0)).collect();
        }
        match convex_hull(&p) {
            Some((v, _)) => v,
            None => p,
        }
    };
    let mut acc = vec![DVec3::ZERO];
    for set in sets {
        let set = reduce(set);
        let sum = acc
            .iter()
            .flat_map(|a| set.iter().map(move |b| *a + *b))
            .collect();
        acc = reduce(sum);
    }
    acc
}

/// The vertices of a primitive, round ones faceted the OpenSCAD way.
fn primitive_points(stmt: &Stmt) -> Result<Vec<DVec3>, CsgError> {
    Ok(match stmt.name.as_str() {
        "sphere" => {
            let r = radius(stmt, "r", "d", 0, 1.0)?;
            if r <= 0.0 {
                return Ok(Vec::new());
            }
            facets::sphere(r, stmt.resolution()?).0
        }
        "cylinder" => match cylinder_params(stmt)? {
            Some((r1, r2, z0, h)) => facets::cylinder(r1, r2, z0, z0 + h, stmt.resolution()?).0,
            None => Vec::new(),
        },
        _ => {
            let size = stmt.size3("size", Some(0), 1.0)?;
            let o = if stmt.flag("center", Some(1), false)? {
                -size / 2.0
            } else {
                DVec3::ZERO
            };
            (0..8)
                .map(|i| {
                    DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64) * size
                        + o
                })
                .collect()
        }
    })
}
