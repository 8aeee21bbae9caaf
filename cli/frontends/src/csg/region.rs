//! A 2D region as explicit polygons: a [`Flat`] program evaluated by polygon clipping
//! (`i_overlay`, exact integer arithmetic on a 64-bit grid fitted to the input), for the
//! operations that need the region's boundary rather than its membership test (offsets that
//! shrink or mitre, Minkowski sums of non-convex operands).
//!
//! A [`Shape`] is one connected region: its outline counter-clockwise first, then its holes
//! clockwise. Discs become polygons: OpenSCAD's n-gons under `--facets openscad`, otherwise
//! polygons whose sagitta is at most [`EXACT_SAGITTA`] of the radius.

use super::Facets;
use super::facets;
use super::flat::{Flat, Leaf2, Op2};
use glam::DVec2;
use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay::ShapeType;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;
use i_overlay::float::simplify::SimplifyShape;
use i_overlay::float::single::SingleFloatOverlay;
use i_overlay::i_float::adapter::FloatPointAdapter;
use i_overlay::i_float::float::rect::FloatRect;

/// One connected region: outline (counter-clockwise), then holes (clockwise).
pub type Shape = Vec<Vec<DVec2>>;

/// The largest sagitta, relative to the radius, of the polygon that stands for an exact disc.
pub const EXACT_SAGITTA: f64 = 1e-5;

/// The most sides of a polygon standing for an exact disc.
const EXACT_SIDES: usize = 1024;

/// The largest coordinate clipping takes (the clipper's own limit is 2⁵⁰⁰; beyond this bound a
/// model's 2D part is refused rather than rounded away).
pub const MAX_COORDINATE: f64 = 1e100;

/// What clipping refuses: a coordinate that is not finite or beyond [`MAX_COORDINATE`].
pub type RegionError = String;

/// The number of sides of a disc whose faceted version (OpenSCAD's) has `openscad` sides.
pub fn disc_sides(openscad: usize, how: Facets) -> usize {
    match how {
        Facets::OpenScad => openscad,
        Facets::Exact => {
            let n = (std::f64::consts::PI / (1.0 - EXACT_SAGITTA).acos()).ceil();
            (n as usize).clamp(3, EXACT_SIDES)
        }
    }
}

/// A disc as a counter-clockwise polygon of `n` sides.
pub fn disc(center: DVec2, r: f64, n: usize) -> Vec<DVec2> {
    facets::circle(r, n)
        .into_iter()
        .map(|p| p + center)
        .collect()
}

fn to_raw(l: &[DVec2]) -> Result<Vec<[f64; 2]>, RegionError> {
    l.iter()
        .map(|p| {
            if p.abs().max_element() <= MAX_COORDINATE {
                Ok([p.x, p.y])
            } else {
                Err(format!(
                    "a 2D coordinate ({:e}, {:e}) is not finite or beyond ±{MAX_COORDINATE:e}, \
                     which polygon clipping does not take",
                    p.x, p.y
                ))
            }
        })
        .collect()
}

fn from_raw(shapes: Vec<Vec<Vec<[f64; 2]>>>) -> Vec<Shape> {
    shapes
        .into_iter()
        .map(|s| {
            s.into_iter()
                .map(|c| c.into_iter().map(|[x, y]| DVec2::new(x, y)).collect())
                .collect()
        })
        .collect()
}

fn raw_shapes(shapes: &[Shape]) -> Result<Vec<Vec<Vec<[f64; 2]>>>, RegionError> {
    shapes
        .iter()
        .map(|s| s.iter().map(|c| to_raw(c)).collect())
        .collect()
}

/// Twice the signed area of a loop.
pub fn area2(l: &[DVec2]) -> f64 {
    (0..l.len())
        .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
        .sum()
}

/// The region of positive winding number of `loops` (a shape's own loops count +1 around its
/// outline and −1 around its holes; add pieces counter-clockwise to unite them with it).
pub fn positive(loops: Vec<Vec<DVec2>>) -> Result<Vec<Shape>, RegionError> {
    let raw: Vec<Vec<[f64; 2]>> = loops
        .iter()
        .filter(|l| l.len() >= 3)
        .map(|l| to_raw(l))
        .collect::<Result<_, _>>()?;
    if raw.is_empty() {
        return Ok(Vec::new());
    }
    Ok(from_raw(raw.simplify_shape_as::<i64>(FillRule::Positive)))
}

/// The loop counter-clockwise.
pub fn ccw(mut l: Vec<DVec2>) -> Vec<DVec2> {
    if area2(&l) < 0.0 {
        l.reverse();
    }
    l
}

/// A Boolean operation of two regions.
pub fn boolean(a: &[Shape], b: &[Shape], rule: OverlayRule) -> Result<Vec<Shape>, RegionError> {
    let (ra, rb) = (raw_shapes(a)?, raw_shapes(b)?);
    if ra.is_empty() && rb.is_empty() {
        return Ok(Vec::new());
    }
    Ok(from_raw(ra.overlay_as::<i64>(&rb, rule, FillRule::NonZero)))
}

/// One integer grid for every clipping step of a region's evaluation, fitted to all of its
/// leaves at once. With a grid per call (the float API's default) each partial result is
/// rounded to its own grid, and pieces that share an edge in the input (OpenSCAD exports a
/// crescent as 16 quads) come apart by that rounding: their union is shapes touching along
/// slivers, not one polygon. On one grid a shared corner is one integer point in every call.
struct Grid(FloatPointAdapter<[f64; 2], i64>);

impl Grid {
    /// The grid of every leaf of `flat` (`None` when it has no leaves); an error for a
    /// coordinate clipping does not take.
    fn of(flat: &Flat) -> Result<Option<Grid>, RegionError> {
        let mut rect: Option<FloatRect<f64>> = None;
        let mut add = |p: DVec2| -> Result<(), RegionError> {
            let [x, y] = to_raw(&[p])?[0];
            match &mut rect {
                Some(r) => r.unsafe_add_point(&[x, y]),
                None => rect = Some(FloatRect::new(x, x, y, y).map_err(|e| format!("{e:?}"))?),
            }
            Ok(())
        };
        for op in &flat.0 {
            match op {
                Op2::Leaf(Leaf2::Circle { center, radius, .. }) => {
                    add(*center - DVec2::splat(*radius))?;
                    add(*center + DVec2::splat(*radius))?;
                }
                Op2::Leaf(Leaf2::Polygon(loops)) => {
                    for p in loops.iter().flatten() {
                        add(*p)?;
                    }
                }
                _ => {}
            }
        }
        Ok(rect.map(|r| Grid(FloatPointAdapter::new_conservative(r))))
    }

    /// `rule` applied to subject and clip loops (`fill` deciding each side's inside).
    fn overlay(
        &self,
        subject: &[Vec<DVec2>],
        clip: &[Vec<DVec2>],
        rule: OverlayRule,
        fill: FillRule,
    ) -> Vec<Shape> {
        let raw = |loops: &[Vec<DVec2>]| -> Vec<Vec<[f64; 2]>> {
            loops
                .iter()
                .filter(|l| l.len() >= 3)
                .map(|l| l.iter().map(|p| [p.x, p.y]).collect())
                .collect()
        };
        let mut overlay = FloatOverlay::<[f64; 2], i64>::with_adapter(self.0.clone(), 0)
            .unsafe_add_source(&raw(subject), ShapeType::Subject)
            .unsafe_add_source(&raw(clip), ShapeType::Clip);
        from_raw(overlay.overlay(rule, fill))
    }

    /// The region of one leaf.
    fn leaf(&self, leaf: &Leaf2, how: Facets) -> Vec<Shape> {
        match leaf {
            Leaf2::Circle {
                center,
                radius,
                res,
            } => {
                let n = disc_sides(facets::fragments(*radius, *res), how);
                let disc = [ccw(disc(*center, *radius, n))];
                self.overlay(&disc, &[], OverlayRule::Subject, FillRule::Positive)
            }
            Leaf2::Polygon(loops) => {
                self.overlay(loops, &[], OverlayRule::Subject, FillRule::EvenOdd)
            }
        }
    }

    /// `op` (a Boolean instruction) of its operands (outlines counter-clockwise and holes
    /// clockwise, so a union is where the winding number is positive): a union or the
    /// subtrahends of a difference in one overlay.
    fn boolean(&self, op: &Op2, parts: Vec<Vec<Shape>>) -> Vec<Shape> {
        let mut parts = parts.into_iter();
        let first: Vec<Vec<DVec2>> = parts
            .next()
            .unwrap_or_default()
            .into_iter()
            .flatten()
            .collect();
        match op {
            Op2::Union(_) => {
                let all: Vec<Vec<DVec2>> =
                    first.into_iter().chain(parts.flatten().flatten()).collect();
                self.overlay(&all, &[], OverlayRule::Subject, FillRule::Positive)
            }
            Op2::Difference(_) => {
                let rest: Vec<Vec<DVec2>> = parts.flatten().flatten().collect();
                self.overlay(&first, &rest, OverlayRule::Difference, FillRule::Positive)
            }
            _ => {
                let first = self.overlay(&first, &[], OverlayRule::Subject, FillRule::Positive);
                parts.fold(first, |acc, p| {
                    let a: Vec<Vec<DVec2>> = acc.into_iter().flatten().collect();
                    let b: Vec<Vec<DVec2>> = p.into_iter().flatten().collect();
                    self.overlay(&a, &b, OverlayRule::Intersect, FillRule::Positive)
                })
            }
        }
    }
}

/// The region a [`Flat`] program describes, as polygons, every step on one grid ([`Grid`]).
pub fn shapes(flat: &Flat, how: Facets) -> Result<Vec<Shape>, RegionError> {
    let Some(grid) = Grid::of(flat)? else {
        return Ok(Vec::new());
    };
    flat.evaluate(
        |leaf| Ok::<_, RegionError>(grid.leaf(leaf, how)),
        |op, parts| grid.boolean(op, parts),
    )
}

/// The shapes as a [`Flat`] (one polygon leaf per shape, united); `None` when there are none.
pub fn to_flat(shapes: Vec<Shape>) -> Option<Flat> {
    let parts: Vec<Flat> = shapes
        .into_iter()
        .filter_map(|s| {
            // Slivers the clipper's grid leaves (a hole of no area beside a glyph's offset): a
            // kernel profile refuses loops of no area relative to their distance from the origin.
            let mut loops = s.into_iter().map(|mut l| {
                l.dedup();
                while l.len() > 1 && l.first() == l.last() {
                    l.pop();
                }
                l
            });
            let keep = |l: &Vec<DVec2>| {
                let scale = l.iter().map(|c| c.length_squared()).fold(0.0, f64::max);
                l.len() >= 3 && area2(l).abs() > 1e-12 * scale
            };
            let outline = loops.next().filter(keep)?;
            let mut kept = vec![outline];
            kept.extend(loops.filter(keep));
            Some(Flat::leaf(Leaf2::Polygon(kept)))
        })
        .collect();
    (!parts.is_empty()).then(|| Flat::combine(parts, Op2::Union))
}

/// The bounding box of the shapes' outlines (`None` when empty).
pub fn bounds(shapes: &[Shape]) -> Option<(DVec2, DVec2)> {
    let mut points = shapes.iter().filter_map(|s| s.first()).flatten().peekable();
    points.peek()?;
    Some(points.fold(
        (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    ))
}

/// The total area of the shapes (outlines minus holes).
#[cfg(test)]
pub fn area(shapes: &[Shape]) -> f64 {
    shapes.iter().flatten().map(|l| area2(l)).sum::<f64>() / 2.0
}

/// How a 2D result differs from OpenSCAD's render (`None` when its area is within 10⁻⁵ of
/// `openscad` in `parts` shapes): the tests' comparison with areas measured on OpenSCAD 2021.01.
#[cfg(test)]
pub fn openscad_mismatch(result: Option<Flat>, openscad: f64, parts: usize) -> Option<String> {
    let shapes = result
        .map(|f| shapes(&f, Facets::OpenScad).expect("clipped"))
        .unwrap_or_default();
    let a = area(&shapes);
    ((a - openscad).abs() > 1e-5 * openscad || shapes.len() != parts).then(|| {
        format!(
            "area {a} in {} parts, OpenSCAD {openscad} in {parts}",
            shapes.len()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(lo: f64, hi: f64) -> Vec<DVec2> {
        vec![
            DVec2::new(lo, lo),
            DVec2::new(hi, lo),
            DVec2::new(hi, hi),
            DVec2::new(lo, hi),
        ]
    }

    #[test]
    fn a_framed_square_is_one_shape_with_a_hole() {
        let flat = Flat(vec![
            Op2::Leaf(Leaf2::Polygon(vec![square(-10.0, 10.0)])),
            Op2::Leaf(Leaf2::Polygon(vec![square(-5.0, 5.0)])),
            Op2::Difference(2),
        ]);
        let s = shapes(&flat, Facets::Exact).unwrap();
        assert_eq!(s.len(), 1);
        assert_eq!(s[0].len(), 2);
        assert!(area2(&s[0][0]) > 0.0 && area2(&s[0][1]) < 0.0);
        assert!((area(&s) - 300.0).abs() < 1e-9);
    }

    #[test]
    fn even_odd_loops_and_exact_discs() {
        // Two loops of one polygon: the inner one is a hole by the even-odd rule.
        let flat = Flat::leaf(Leaf2::Polygon(vec![square(0.0, 4.0), square(1.0, 2.0)]));
        assert!((area(&shapes(&flat, Facets::Exact).unwrap()) - 15.0).abs() < 1e-9);
        let disc = Flat::leaf(Leaf2::Circle {
            center: DVec2::ZERO,
            radius: 2.0,
            res: facets::Resolution {
                fn_: 0.0,
                fa: 12.0,
                fs: 2.0,
            },
        });
        let a = area(&shapes(&disc, Facets::Exact).unwrap());
        assert!((a - 4.0 * std::f64::consts::PI).abs() < 4.0 * std::f64::consts::PI * 2e-5);
        let faceted = area(&shapes(&disc, Facets::OpenScad).unwrap());
        assert!(faceted < a * 0.99, "OpenSCAD's default disc has few sides");
    }

    #[test]
    fn intersections_and_unions() {
        let flat = Flat(vec![
            Op2::Leaf(Leaf2::Polygon(vec![square(0.0, 2.0)])),
            Op2::Leaf(Leaf2::Polygon(vec![square(1.0, 3.0)])),
            Op2::Intersection(2),
            Op2::Leaf(Leaf2::Polygon(vec![square(5.0, 6.0)])),
            Op2::Union(2),
        ]);
        let s = shapes(&flat, Facets::Exact).unwrap();
        assert_eq!(s.len(), 2);
        assert!((area(&s) - 2.0).abs() < 1e-9);
        let back = to_flat(s).expect("two shapes");
        assert_eq!(back.leaf_count(), 2);
    }

    /// The clipper's grid can leave a hole of no area (Debian's `Advanced_GEB`: a glyph's round
    /// offset); a kernel profile refuses it, so the region drops it.
    #[test]
    fn loops_of_no_area_are_dropped() {
        let shape = vec![
            square(0.0, 4.0),
            vec![
                DVec2::new(1.0, 1.0),
                DVec2::new(2.0, 1.0),
                DVec2::new(2.0, 1.0),
                DVec2::new(3.0, 1.0),
            ],
        ];
        let flat = to_flat(vec![
            shape,
            vec![vec![DVec2::ZERO, DVec2::X, DVec2::X * 2.0]],
        ])
        .expect("the square stays");
        assert_eq!(
            flat.0,
            vec![Op2::Leaf(Leaf2::Polygon(vec![square(0.0, 4.0)]))]
        );
    }

    /// OpenSCAD exports a crescent as quads sharing edges, corners to 6 significant digits
    /// (Debian's `Old_example020`); their union is one polygon, whatever grid the clipper
    /// fits, and so is the same crescent cut from a disc by the quads as subtrahends.
    #[test]
    fn pieces_sharing_edges_unite_into_one_shape() {
        let round = |v: f64| (v * 1e4).round() / 1e4;
        let at = |r: f64, deg: f64| {
            let (s, c) = deg.to_radians().sin_cos();
            DVec2::new(round(r * c), round(r * s))
        };
        let quads: Vec<Flat> = (0..16)
            .map(|i| {
                let (a, b) = (i as f64 * 18.75, (i + 1) as f64 * 18.75);
                let quad = vec![at(110.0, a), at(90.0, a), at(90.0, b), at(110.0, b)];
                Flat::leaf(Leaf2::Polygon(vec![quad]))
            })
            .collect();
        let united = shapes(&Flat::combine(quads.clone(), Op2::Union), Facets::OpenScad).unwrap();
        assert_eq!(united.len(), 1, "{} shapes", united.len());
        assert_eq!(united[0].len(), 1, "no slits inside");
        let disc = Flat::leaf(Leaf2::Polygon(vec![square(-200.0, 200.0)]));
        let mut parts = vec![disc];
        parts.extend(quads);
        let cut = shapes(&Flat::combine(parts, Op2::Difference), Facets::OpenScad).unwrap();
        assert_eq!(cut.len(), 1);
        assert_eq!(cut[0].len(), 2, "the square with one crescent-shaped hole");
        assert!((area(&cut) - (400.0 * 400.0 - area(&united))).abs() < 1e-6);
    }
}
