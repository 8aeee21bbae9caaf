//! The functions and methods scripts call: primitives, Booleans (functions on arrays and the
//! operators `|`, `&`, `-`), transforms, blends, `expr` (formula solids), `node(map)` for every
//! other family, `dual` (of a convex polyhedral leaf), `export`.

use super::node;
use super::shape::{Fallible, Shape, fail, num, num_or_vec3, shapes, vec3};
use rhai::{Array, Dynamic, Engine, Map};
use solidkit_kernel::Aabb;
use solidkit_kernel::Rgba;
use solidkit_kernel::Solid;
use solidkit_kernel::json::MeshResolver;
use solidkit_kernel::primitive::{Expr, Gyroid, Primitive};
use std::sync::{Arc, Mutex};

/// Builds nodes within the tree-size budget.
#[derive(Clone, Copy)]
struct Budget(u64);

impl Budget {
    /// A node over `children`, or the budget error.
    fn node(self, children: &[Shape], build: impl FnOnce(Vec<Solid>) -> Solid) -> Fallible<Shape> {
        super::check_deadline()?;
        let nodes = children.iter().fold(1u64, |n, c| n.saturating_add(c.nodes));
        if nodes > self.0 {
            return fail(format!(
                "the solid would have {nodes} nodes, more than the limit of {} \
                 (shared subtrees count once per use)",
                self.0
            ));
        }
        let solids = children.iter().map(|c| c.solid.clone()).collect();
        Ok(Shape {
            solid: build(solids),
            nodes,
        })
    }

    /// A one-child node.
    fn unary(self, s: &Shape, build: impl FnOnce(&Solid) -> Solid) -> Fallible<Shape> {
        self.node(std::slice::from_ref(s), |c| build(&c[0]))
    }
}

/// Registers the whole API on `engine`.
pub(super) fn register(
    engine: &mut Engine,
    max_nodes: u64,
    resolver: Arc<dyn MeshResolver + Send + Sync>,
    exported: Arc<Mutex<Option<Shape>>>,
) {
    engine.register_type_with_name::<Shape>("Solid");
    engine.register_fn("to_string", |s: &mut Shape| {
        format!("Solid({}, {} nodes)", s.solid.kind().name(), s.nodes)
    });
    primitives(engine);
    booleans(engine, Budget(max_nodes));
    transforms(engine, Budget(max_nodes));
    blends(engine, Budget(max_nodes));
    let dual_resolver = resolver.clone();
    // `dual(solid)`: the dual of a convex polyhedral leaf (platonic, polyhedron, prism, mesh).
    engine.register_fn("dual", move |s: Shape| -> Fallible<Shape> {
        super::check_deadline()?;
        match s.solid.dual(dual_resolver.as_ref()) {
            Ok(solid) => Ok(Shape { solid, nodes: 1 }),
            Err(e) => fail(format!("dual: {e}")),
        }
    });
    engine.register_fn("node", move |m: Map| -> Fallible<Shape> {
        super::check_deadline()?;
        let shape = node::from_map(m, resolver.as_ref(), max_nodes)?;
        // Reading meshes or building large polyhedra may take long: stop right after.
        super::check_deadline()?;
        Ok(shape)
    });
    // `export` is a reserved word of Rhai, so `export(solid)` is a syntax of its own.
    engine
        .register_custom_syntax(["export", "(", "$expr$", ")"], false, move |ctx, inputs| {
            let value = ctx.eval_expression_tree(&inputs[0])?;
            let name = value.type_name();
            let Some(shape) = value.clone().try_cast::<Shape>() else {
                return fail(format!("export: expected a Solid, found {name}"));
            };
            if let Ok(mut slot) = exported.lock() {
                *slot = Some(shape);
            }
            Ok(value)
        })
        .expect("`export ( expr )` is a valid custom syntax");
}

fn leaf(solid: Solid) -> Fallible<Shape> {
    super::check_deadline()?;
    Ok(Shape::leaf(solid))
}

fn primitives(engine: &mut Engine) {
    engine.register_fn("sphere", |r: Dynamic| {
        leaf(Solid::sphere(num(&r, "sphere radius")?))
    });
    engine.register_fn("cube", |s: Dynamic| {
        leaf(Solid::cuboid(num_or_vec3(&s, "cube size")?))
    });
    for name in ["box", "cuboid"] {
        engine.register_fn(name, |s: Dynamic| {
            leaf(Solid::cuboid(num_or_vec3(&s, "box size")?))
        });
    }
    engine.register_fn("cylinder", |r: Dynamic, h: Dynamic| {
        leaf(Solid::cylinder(
            num(&r, "cylinder radius")?,
            num(&h, "cylinder height")?,
        ))
    });
    engine.register_fn("cone", |r1: Dynamic, r2: Dynamic, h: Dynamic| {
        leaf(Solid::cone(
            num(&r1, "cone bottom radius")?,
            num(&r2, "cone top radius")?,
            num(&h, "cone height")?,
        ))
    });
    engine.register_fn("torus", |big: Dynamic, small: Dynamic| {
        leaf(Solid::torus(
            num(&big, "torus major radius")?,
            num(&small, "torus minor radius")?,
        ))
    });
    engine.register_fn("plane", |n: Dynamic, d: Dynamic| {
        leaf(Solid::half_space(
            vec3(&n, "plane normal")?,
            num(&d, "plane offset")?,
        ))
    });
    engine.register_fn("gyroid", |t: Dynamic| {
        leaf(Solid::primitive(Primitive::Gyroid(Gyroid {
            thickness: num(&t, "gyroid thickness")?,
        })))
    });
    // `expr("x*x + y*y - z", [x0, y0, z0], [x1, y1, z1])`: a formula cut by a box.
    engine.register_fn(
        "expr",
        |formula: &str, min: Dynamic, max: Dynamic| -> Fallible<Shape> {
            let bounds = Aabb::new(vec3(&min, "expr min")?, vec3(&max, "expr max")?);
            match Expr::new(formula, bounds) {
                Ok(e) => leaf(Solid::primitive(Primitive::Expr(Arc::new(e)))),
                Err(e) => fail(format!("expr: {e}")),
            }
        },
    );
}

fn booleans(engine: &mut Engine, b: Budget) {
    engine.register_fn("union", move |a: Array| {
        b.node(&shapes(a, "union")?, Solid::union_all)
    });
    engine.register_fn("intersection", move |a: Array| {
        b.node(&shapes(a, "intersection")?, Solid::intersection_all)
    });
    engine.register_fn("difference", move |a: Array| {
        let s = shapes(a, "difference")?;
        if s.is_empty() {
            return fail("difference: needs at least one solid");
        }
        b.node(&s, |c| {
            let mut c = c.into_iter();
            let base = c.next().expect("checked non-empty");
            Solid::difference_all(base, c)
        })
    });
    engine.register_fn("union", move |x: Shape, y: Shape| {
        b.node(&[x, y], Solid::union_all)
    });
    engine.register_fn("intersection", move |x: Shape, y: Shape| {
        b.node(&[x, y], Solid::intersection_all)
    });
    engine.register_fn("difference", move |x: Shape, y: Shape| {
        b.node(&[x, y], |c| Solid::difference(&c[0], &c[1]))
    });
    engine.register_fn("|", move |x: Shape, y: Shape| {
        b.node(&[x, y], Solid::union_all)
    });
    engine.register_fn("&", move |x: Shape, y: Shape| {
        b.node(&[x, y], Solid::intersection_all)
    });
    engine.register_fn("-", move |x: Shape, y: Shape| {
        b.node(&[x, y], |c| Solid::difference(&c[0], &c[1]))
    });
}

fn transforms(engine: &mut Engine, b: Budget) {
    engine.register_fn("translate", move |s: Shape, v: Dynamic| {
        let v = vec3(&v, "translate offset")?;
        b.unary(&s, |c| c.translate(v))
    });
    engine.register_fn("rotate", move |s: Shape, axis: Dynamic, deg: Dynamic| {
        let axis = vec3(&axis, "rotate axis")?;
        let deg = num(&deg, "rotate degrees")?;
        b.unary(&s, |c| c.rotate(axis, deg))
    });
    engine.register_fn("scale", move |s: Shape, k: Dynamic| {
        let k = num_or_vec3(&k, "scale factor")?;
        b.unary(&s, |c| c.scale(k))
    });
    engine.register_fn("mirror", move |s: Shape, n: Dynamic| {
        let n = vec3(&n, "mirror normal")?;
        b.unary(&s, |c| c.mirror(n))
    });
    engine.register_fn("affine", move |s: Shape, rows: Array| {
        let m = matrix(rows)?;
        b.unary(&s, |c| c.affine(m))
    });
    engine.register_fn("offset", move |s: Shape, d: Dynamic| {
        let d = num(&d, "offset distance")?;
        b.unary(&s, |c| c.offset(d))
    });
    engine.register_fn("shell", move |s: Shape, t: Dynamic| {
        let t = num(&t, "shell thickness")?;
        b.unary(&s, |c| c.shell(t))
    });
    engine.register_fn("color", move |s: Shape, c: Dynamic| {
        let c = color(&c, None)?;
        b.unary(&s, |s| s.color(c))
    });
    engine.register_fn("color", move |s: Shape, c: Dynamic, alpha: Dynamic| {
        let alpha = num(&alpha, "color alpha")?;
        let c = color(&c, Some(alpha))?;
        b.unary(&s, |s| s.color(c))
    });
}

/// A colour from a name or `"#rrggbb[aa]"` string or an array of 3 or 4 numbers in 0..1, with
/// `alpha` replacing the alpha of a name or an `[r, g, b]`.
fn color(c: &Dynamic, alpha: Option<f64>) -> Fallible<Rgba> {
    let what = "color: expected a colour name, \"#rrggbb\", [r, g, b] or [r, g, b, a]";
    let rgba = if let Some(s) = c.clone().try_cast::<rhai::ImmutableString>() {
        let Some(c) = Rgba::parse(&s) else {
            return fail(format!("color: unknown colour {:?}", s.as_str()));
        };
        match alpha {
            Some(a) if !(s.starts_with('#') && matches!(s.len(), 5 | 9)) => c.with_alpha(a as f32),
            _ => c,
        }
    } else if let Some(items) = c.clone().try_cast::<Array>() {
        let v = items
            .iter()
            .map(|x| num(x, "color channel").map(|x| x as f32))
            .collect::<Fallible<Vec<f32>>>()?;
        match (v.as_slice(), alpha) {
            (&[r, g, b], a) => Rgba([r, g, b, a.map_or(1.0, |a| a as f32)]),
            (&[r, g, b, a], _) => Rgba([r, g, b, a]),
            _ => return fail(what),
        }
    } else {
        return fail(what);
    };
    match rgba.problem() {
        Some(p) => fail(p),
        None => Ok(rgba),
    }
}

/// A 3 × 4 row-major matrix from three arrays of four numbers.
fn matrix(rows: Array) -> Fallible<[[f64; 4]; 3]> {
    if rows.len() != 3 {
        return fail("affine matrix: expected 3 rows of 4 numbers");
    }
    let mut m = [[0.0; 4]; 3];
    for (out, row) in m.iter_mut().zip(rows) {
        let Some(row) = row.try_cast::<Array>().filter(|r| r.len() == 4) else {
            return fail("affine matrix: expected 3 rows of 4 numbers");
        };
        for (o, v) in out.iter_mut().zip(&row) {
            *o = num(v, "affine matrix")?;
        }
    }
    Ok(m)
}

fn blends(engine: &mut Engine, b: Budget) {
    type Build = fn(Vec<Solid>, f64) -> Solid;
    let kinds: [(&str, Build); 3] = [
        ("smooth_union", |c, r| Solid::smooth_union_all(c, r)),
        ("smooth_intersection", |c, r| {
            Solid::smooth_intersection_all(c, r)
        }),
        ("smooth_difference", |c, r| {
            let mut c = c.into_iter();
            match c.next() {
                Some(base) => Solid::smooth_difference_all(base, c, r),
                None => Solid::smooth_difference_all(Solid::union_all([]), [], r),
            }
        }),
    ];
    for (name, build) in kinds {
        engine.register_fn(name, move |x: Shape, y: Shape, r: Dynamic| {
            let r = num(&r, "blend radius")?;
            b.node(&[x, y], |c| build(c, r))
        });
        engine.register_fn(name, move |a: Array, r: Dynamic| {
            let r = num(&r, "blend radius")?;
            let s = shapes(a, name)?;
            if s.is_empty() {
                return fail(format!("{name}: needs at least one solid"));
            }
            b.node(&s, |c| build(c, r))
        });
    }
}
