//! The exhaustive test behind [`super::disjoint`]: no two triangles of a case-table entry with at
//! most [`PROVEN_TRIANGLES`] triangles meet beyond the crossings they share, wherever the
//! crossings lie strictly inside their edges (larger entries are tested cell by cell at run time,
//! and this test shows why: some of their pairs can meet).
//!
//! Two triangles of an entry depend only on the crossings they use (at most six edges), so every
//! distinct pair of triangles over all configurations (mask and joined faces) is tested once, on
//! the unit cell, with the project's exact triangle–triangle test
//! ([`crate::intersect::pair_meets`]): every combination of the crossing parameters
//! `{ε, 0.25, 0.5, 0.75, 1 − ε}` (ε = 10⁻⁹, far closer to a sample than
//! [`EDGE_MARGIN`](super::EDGE_MARGIN) puts a vertex before rounding) on each of its edges, then
//! random parameters in `(0, 1)`, a quarter of them within `1e-12..1e-2` of an end. Configurations with a centre vertex are tested whole, with the centre
//! at the centroid of the loop's crossings as the polygonizers place it. Each triangle is also
//! checked non-degenerate. Intersection is invariant under the per-axis scaling from the unit cell
//! to a real (rounded) cell box, so this covers every cell of every grid.
//!
//! `SOLIDKIT_MC_EXHAUSTIVE=N` multiplies the random draws by `N` (the default run takes a few
//! seconds in release).

use super::disjoint::PROVEN_TRIANGLES;
use super::table::{CENTRE, NO_CENTRE, case_table, corner_offset, edge_corners};
use crate::grid::GridSpec;
use crate::intersect::pair_meets;
use glam::DVec3;
use std::collections::BTreeSet;

/// The lattice's closest approach to a sample.
const EPS: f64 = 1e-9;

/// Every distinct configuration: each mask with each subset of its ambiguous faces joined.
fn configs() -> Vec<usize> {
    let t = case_table();
    (0..256usize)
        .flat_map(|mask| {
            let amb = t.ambiguous[mask];
            (0..64u8)
                .filter(move |j| j & !amb == 0)
                .map(move |j| mask | usize::from(j) << 8)
        })
        .collect()
}

/// The point at parameter `t` along cell edge `e` of the unit cell.
fn on_edge(e: u8, t: f64) -> DVec3 {
    let (a, b) = edge_corners(e);
    let p = |c: u8| {
        let o = corner_offset(c);
        DVec3::new(o[0] as f64, o[1] as f64, o[2] as f64)
    };
    p(a) + (p(b) - p(a)) * t
}

struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A crossing parameter in `(0, 1)`: three quarters uniform, a quarter log-uniform within
    /// `1e-12..1e-2` of an end (rounding a vertex to single precision can bring it closer to a
    /// sample than [`EDGE_MARGIN`](super::EDGE_MARGIN); the mesher certifies only vertices
    /// strictly inside their rounded edges).
    fn param(&mut self) -> f64 {
        let u = self.unit();
        if self.unit() < 0.25 {
            let d = 10f64.powf(-12.0 + 10.0 * self.unit());
            if u < 0.5 { d } else { 1.0 - d }
        } else {
            u.clamp(1e-12, 1.0 - 1e-12)
        }
    }
}

fn scale() -> usize {
    std::env::var("SOLIDKIT_MC_EXHAUSTIVE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

/// A failure, with the triangles and parameters, or `None`.
fn check(tris: &[[u8; 3]], t: &[f64; 13]) -> Option<String> {
    let pos = |e: u8| {
        if e == CENTRE {
            DVec3::new(t[12], 0.0, 0.0) // replaced below
        } else {
            on_edge(e, t[usize::from(e)])
        }
    };
    let centre = tris.iter().flatten().any(|&e| e == CENTRE).then(|| {
        let edges: BTreeSet<u8> = tris
            .iter()
            .flatten()
            .copied()
            .filter(|&e| e != CENTRE && tris.iter().any(|t| t.contains(&e) && t.contains(&CENTRE)))
            .collect();
        edges.iter().map(|&e| pos(e)).sum::<DVec3>() / edges.len() as f64
    });
    let corners = |tri: [u8; 3]| {
        tri.map(|e| {
            if e == CENTRE {
                centre.unwrap_or_default()
            } else {
                pos(e)
            }
        })
    };
    for (i, &a) in tris.iter().enumerate() {
        for &b in &tris[i + 1..] {
            let ids = |x: [u8; 3]| x.map(u32::from);
            if pair_meets(ids(a), corners(a), ids(b), corners(b)) {
                return Some(format!("{a:?} {b:?} at {t:?}"));
            }
        }
    }
    None
}

/// Every pair of triangles of every table entry, on the parameter lattice and at random.
#[test]
fn no_two_triangles_of_a_cell_meet_beyond_shared_crossings() {
    let table = case_table();
    let mut pairs = std::collections::BTreeMap::new();
    let mut centred = Vec::new();
    for config in configs() {
        let tris = table.triangles(config);
        if table.centre_loop[config] != NO_CENTRE {
            centred.push(config);
            continue;
        }
        for (i, a) in tris.iter().enumerate() {
            for b in &tris[i + 1..] {
                let (mut a, mut b) = (*a, *b);
                a.sort_unstable();
                b.sort_unstable();
                let n = pairs
                    .entry(if a < b { (a, b) } else { (b, a) })
                    .or_insert(tris.len());
                *n = (*n).min(tris.len());
            }
        }
    }
    const LATTICE: [f64; 5] = [EPS, 0.25, 0.5, 0.75, 1.0 - EPS];
    let mut rng = Rng(0x5EED);
    let mut tested = 0u64;
    let mut failures = Vec::new();
    let mut kinds = std::collections::BTreeMap::<(usize, usize), [usize; 2]>::new();
    for (&(a, b), &ntri) in &pairs {
        let shared = a.iter().filter(|e| b.contains(e)).count();
        let kind = kinds.entry((shared, ntri)).or_default();
        kind[0] += 1;
        let edges: Vec<u8> = a
            .iter()
            .chain(&b)
            .copied()
            .collect::<BTreeSet<u8>>()
            .into_iter()
            .collect();
        let combos = LATTICE.len().pow(edges.len() as u32);
        let mut t = [0.5; 13];
        for n in 0..combos + 1000 * scale() {
            let mut k = n;
            for &e in &edges {
                t[usize::from(e)] = if n < combos {
                    let v = LATTICE[k % LATTICE.len()];
                    k /= LATTICE.len();
                    v
                } else {
                    rng.param()
                };
            }
            tested += 1;
            if let Some(f) = check(&[a, b], &t) {
                failures.push(f);
                kind[1] += 1;
                break;
            }
        }
    }
    let mut whole = 0u64;
    let mut centred_meeting = 0;
    for &config in &centred {
        let tris = table.triangles(config);
        let mut t = [0.5; 13];
        for n in 0..2000 * scale() {
            for v in &mut t[..12] {
                *v = if n == 0 { 0.5 } else { rng.param() };
            }
            whole += 1;
            // Informative only: these cells are always tested at run time.
            if check(tris, &t).is_some() {
                centred_meeting += 1;
                break;
            }
        }
    }
    let proven: Vec<_> = kinds
        .iter()
        .filter(|((_, n), _)| *n <= PROVEN_TRIANGLES)
        .collect();
    let unsafe_pairs: usize = kinds.values().map(|v| v[1]).sum();
    eprintln!(
        "{} distinct triangle pairs, {} in entries of at most {PROVEN_TRIANGLES} triangles; {tested} pair tests; \
         {unsafe_pairs} pairs of larger entries can meet; {} centred configurations, {whole} whole-cell tests, {centred_meeting} meeting",
        pairs.len(),
        proven.iter().map(|(_, v)| v[0]).sum::<usize>(),
        centred.len(),
    );
    eprintln!("(shared crossings, fewest triangles of an entry with the pair): [pairs, can meet]");
    for (k, v) in &kinds {
        eprintln!("{k:?}: {v:?}");
    }
    for f in failures.iter().take(5) {
        eprintln!("can meet: {f}");
    }
    assert!(pairs.len() > 1000 && !centred.is_empty());
    // What the run relies on: every pair of a small entry is safe.
    for ((shared, n), v) in &proven {
        assert_eq!(
            v[1], 0,
            "pairs sharing {shared} crossings in entries of {n} triangles meet"
        );
    }
    assert!(proven.iter().map(|(_, v)| v[0]).sum::<usize>() > 500);
    // The test finds intersections where there are some: larger entries need the cell test.
    assert!(unsafe_pairs > 0);
}

/// Cross-validation on whole runs: marching-cubes meshes of a few models (smooth, a box on
/// sample planes with exact zeros, a Menger sponge with faces flush against each other, the
/// gyroid with ambiguous faces and tunnel cells, one refined for a thin plate, one cut at its
/// grid's edge) report "construction" from marching cubes and from dual contouring (but for the
/// open cut sphere), and the full test finds no pair on the same meshes.
#[test]
fn construction_claims_agree_with_the_full_test() {
    use crate::intersect::self_intersections;
    use crate::pipeline::{Domain, MeshOptions, Method, mesh_solid};
    use crate::{ReportOptions, SelfIntersectionsMethod};
    use solidkit_kernel::Solid;
    use solidkit_kernel::models::Model;

    let model = |name: &str| {
        let m = Model::by_name(name).expect("model");
        (m.solid, Domain::Covering(m.domain))
    };
    let plate = Solid::cuboid(DVec3::new(1.0, 1.0, 0.04));
    let cases = [
        ("sphere", model("sphere"), 40),
        ("gyroid-sphere", model("gyroid-sphere"), 48),
        ("menger-4", model("menger-4"), 54),
        (
            "box on sample planes",
            (Solid::cuboid(DVec3::splat(1.0)), Domain::Solid),
            16,
        ),
        ("thin plate, refined", (plate, Domain::Solid), 10),
        (
            "sphere cut by its box",
            (
                Solid::sphere(1.0),
                Domain::Grid(GridSpec {
                    origin: DVec3::splat(-0.9),
                    cell: 0.1,
                    cells: [18; 3],
                }),
            ),
            18,
        ),
    ];
    for (name, (solid, domain), n) in cases {
        for method in [Method::Mc, Method::Dc] {
            let start = std::time::Instant::now();
            let mut options = MeshOptions::new(n).method(method).domain(domain);
            if name != "thin plate, refined" {
                options = options.no_refinement();
            }
            let meshed = mesh_solid(&solid, &options).expect("meshes");
            assert!(!meshed.mesh.triangles.is_empty(), "{name}");
            let r = meshed.report(&ReportOptions::default());
            // Dual contouring leaves the edges at a grid's edge without polygons where the
            // solid reaches it (an open mesh): that run claims nothing.
            let expected = if method == Method::Dc && name == "sphere cut by its box" {
                SelfIntersectionsMethod::Tested
            } else {
                SelfIntersectionsMethod::Construction
            };
            assert_eq!(
                r.self_intersections_method,
                Some(expected),
                "{name} {method:?}"
            );
            assert_eq!(r.self_intersections, Some(0), "{name} {method:?}");
            let tested = self_intersections(&meshed.mesh, 8).expect("finite");
            assert_eq!(tested.count, 0, "{name} {method:?}: {:?}", tested.examples);
            if name == "thin plate, refined" {
                assert!(meshed.factor > 1, "the plate refines");
            }
            eprintln!(
                "{name} {method:?}: {} triangles, {:.2} s",
                meshed.mesh.triangles.len(),
                start.elapsed().as_secs_f64()
            );
        }
    }
}

/// A run whose vertices round onto their samples (a tiny cell far from the origin) does not
/// claim the guarantee, with either mesher: the report tests.
#[test]
fn tiny_cells_far_out_are_tested() {
    use crate::pipeline::{Domain, MeshOptions, Method, mesh_solid};
    use crate::{ReportOptions, SelfIntersectionsMethod};
    use solidkit_kernel::Solid;

    let centre = DVec3::splat(3000.0);
    let solid = Solid::sphere(0.01).translate(centre);
    let spec = GridSpec {
        origin: centre - 0.012,
        cell: 0.024 / 24.0,
        cells: [24; 3],
    };
    for method in [Method::Mc, Method::Dc] {
        let options = MeshOptions::new(24)
            .method(method)
            .domain(Domain::Grid(spec))
            .no_refinement();
        let meshed = mesh_solid(&solid, &options).expect("meshes");
        assert!(!meshed.mesh.triangles.is_empty());
        let r = meshed.report(&ReportOptions::default());
        assert_eq!(
            r.self_intersections_method,
            Some(SelfIntersectionsMethod::Tested),
            "{method:?}"
        );
    }
}
