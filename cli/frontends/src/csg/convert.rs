//! The statement tree to a [`Solid`], post-order over an explicit work list: each statement's
//! geometry is built from its children's (3D solids, or 2D [`Flat`] programs under extrusions).

use super::Facets;
use super::error::{CsgError, Warning};
use super::facets;
use super::flat::{Flat, Leaf2, Op2};
use super::geom::{Ctx, Geom};
use super::hullable::{Hullable, hullable_of};
use super::hulled::hull;
use super::import::{Imported, import, string_arg};
use super::minkowski::minkowski;
use super::offset::{Offset, offset};
use super::parser::{Stmt, Tree, Value};
use super::polyhedral::{self, Track};
use super::projection::projection;
use super::resize::resize;
use super::shape_args::{cylinder, faceted_solid, is_identity, matrix, polyhedron, radius};
use super::sliced;
use super::surface::surface;
use super::sweep::{reach, sweep, sweep_solid, x_range};
use super::text::{TextCache, text};
use super::turned;
use glam::{DVec2, DVec3};
use solidkit_kernel::Solid;
use solidkit_kernel::primitive::{Extrude, MeshResolver, Primitive, Revolve};
use solidkit_meshing::polyhedral::Polyhedral;
use std::sync::Arc;

/// Converts the whole tree (top-level statements form an implicit group): statements marked `%`
/// or `*` are left out, and the first statement marked `!` is the whole model. Parts OpenSCAD
/// skips with a warning are skipped here too, and their warnings returned.
pub fn convert(
    tree: &Tree,
    facets: Facets,
    files: &dyn MeshResolver,
) -> Result<(Solid, Vec<Warning>), CsgError> {
    convert_with(tree, facets, files, false, None).map(|(s, w, _)| (s, w))
}

/// [`convert`], and with `polyhedral` also the model's polyhedron (`polyhedral.rs`) or the
/// first statement that has none. With `part_grid`, a statement with no polyhedral form is
/// meshed on a grid of that many cells along its own longest side instead (with a warning), so
/// only that part carries a grid's error.
pub fn convert_with(
    tree: &Tree,
    facets: Facets,
    files: &dyn MeshResolver,
    polyhedral: bool,
    part_grid: Option<usize>,
) -> Result<(Solid, Vec<Warning>, Option<Track>), CsgError> {
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
    let mut polys: Vec<Option<Track>> = vec![None; tree.nodes.len()];
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
        let mut infos: Vec<Option<Hullable>> = kids.iter().map(|&c| hullable[c].take()).collect();
        let mut kid_polys: Vec<Option<Track>> = if polyhedral {
            kids.iter().map(|&c| polys[c].take()).collect()
        } else {
            Vec::new()
        };
        let (dims, flat) = if polyhedral {
            (polyhedral::dims(&children), polyhedral::flat_of(&children))
        } else {
            (Vec::new(), None)
        };
        if polyhedral && stmt.name == "hull" {
            // An operand known only from its geometry: its polyhedron's vertices are exact
            // where a fine mesh's would not be.
            for (info, poly) in infos.iter_mut().zip(&kid_polys) {
                if info.is_none()
                    && let Some(Ok(p)) = poly
                {
                    *info = Some(Hullable {
                        points: p.to_mesh().positions,
                        convex: false,
                        pieces: None,
                    });
                }
            }
        }
        // The polyhedra's exact projection, where every 3D child has one; else it is sampled.
        let projected = (polyhedral && stmt.name == "projection")
            .then(|| polyhedral::projection(stmt, &dims, &mut kid_polys))
            .flatten();
        let (geom, info) = match stmt.name.as_str() {
            "hull" => hull(stmt, children, infos, &mut ctx)?,
            "minkowski" => minkowski(tree, &kids, stmt, children, infos, &mut ctx)?,
            _ => {
                let facets = if hulled { Facets::OpenScad } else { facets };
                let geom = match projected {
                    Some(region) => {
                        if dims.contains(&polyhedral::Dim::Flat) {
                            ctx.warn(stmt, "ignoring 2D child object for projection");
                        }
                        region.map_or(Geom::Empty, Geom::Flat)
                    }
                    None => node(stmt, children, facets, &mut ctx)?,
                };
                let info = if hulled {
                    hullable_of(stmt, &geom, infos)?
                } else {
                    None
                };
                (geom, info)
            }
        };
        if polyhedral {
            let mut track =
                polyhedral::track(stmt, &dims, kid_polys, flat.as_ref(), &geom, info.as_ref());
            if let (Some(Err(why)), Some(cells), Geom::Solid(solid)) = (&track, part_grid, &geom)
                && let Ok(p) = Polyhedral::gridded(solid, cells)
            {
                ctx.warn(
                    stmt,
                    format!(
                        "{} has no polyhedral form: meshed on a grid of {cells} cells along its \
                         longest side, then combined exactly with the rest",
                        why.message
                    ),
                );
                track = Some(Ok(p));
            }
            polys[i] = track;
        }
        results[i] = Some(geom);
        if hulled {
            hullable[i] = info;
        }
    }
    let top: Vec<Geom> = roots
        .iter()
        .map(|&r| results[r].take().expect("root converted"))
        .collect();
    let track = polyhedral.then(|| {
        let root_dims = polyhedral::dims(&top);
        let parts: Vec<Option<Track>> = roots.iter().map(|&r| polys[r].take()).collect();
        polyhedral::union_track(&root_dims, parts)
    });
    let root = Stmt {
        name: "group".into(),
        ..Stmt::default()
    };
    let solid = match group(&root, top, Op2::Union, &mut ctx)? {
        Geom::Solid(s) => s,
        Geom::Empty => {
            let skipped = match ctx.warnings.as_slice() {
                [] => String::new(),
                [one] => format!("; skipped: {one}"),
                [first, rest @ ..] => format!("; skipped: {first} (and {} more)", rest.len()),
            };
            return Err(CsgError::Empty(skipped));
        }
        Geom::Flat(_) => return Err(CsgError::Flat),
    };
    Ok((solid, ctx.warnings, track))
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
        let intersection = matches!(op(0), Op2::Intersection(_));
        ctx.warn(
            stmt,
            format!(
                "mixing 2D and 3D objects is not supported: the first child is {kept}, \
                 the {dropped} children are ignored{}",
                if intersection {
                    " and leave the intersection empty"
                } else {
                    ""
                }
            ),
        );
        // OpenSCAD 2021.01 keeps an ignored child of `intersection()` as an empty operand, so
        // the whole intersection is empty (measured: a cube intersected with a circle renders
        // nothing, in either order).
        if intersection {
            return Ok(Geom::Empty);
        }
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
            let (mut faces, cleaned) = super::faces::clean_faces(&points, faces);
            if super::faces::inside_out(&points, &faces) {
                for f in &mut faces {
                    f.reverse();
                }
            }
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
            let bytes = match ctx.files.read_file(path) {
                Ok(b) => b,
                // OpenSCAD warns about a file it cannot open and renders nothing for it.
                Err(e) if super::import::missing(&e) => {
                    ctx.warn(stmt, format!("{e}: the surface is empty"));
                    return leaf(Geom::Empty);
                }
                Err(e) => return Err(stmt.error(e.to_string())),
            };
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
            // OpenSCAD: `r` (the one positional argument) if given, else `delta` if given,
            // else `r = 1`.
            let how = if stmt.arg("r", Some(0)).is_some() || stmt.arg("delta", None).is_none() {
                Offset::Round {
                    r: stmt.num("r", Some(0), 1.0)?,
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
            Ok(offset(flat, how, ctx.facets)
                .map_err(|e| stmt.error(e))?
                .map_or(Geom::Empty, Geom::Flat))
        }
        other => Err(CsgError::Unsupported {
            pos: stmt.pos,
            name: other.to_string(),
        }),
    }
}
