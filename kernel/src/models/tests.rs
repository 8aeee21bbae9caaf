//! Unit tests of the models: node counts, exact values and determinism (meshing-based checks of
//! volume and genus live in the `solidkit-tests` crate, which can depend on the mesher).

use super::workload::{lattice_points, octree_boxes};
use super::*;
use crate::program::BatchScratch;

fn gyroid_formula(p: DVec3) -> f64 {
    let q = p * GYROID_SCALE;
    let g = q.x.sin() * q.y.cos() + q.y.sin() * q.z.cos() + q.z.sin() * q.x.cos();
    (q.length() - GYROID_SPHERE_RADIUS).max(g.abs() - GYROID_THICKNESS)
}

#[test]
fn sphere_is_the_exact_distance() {
    let s = sphere_bench();
    assert_eq!(s.node_count(), 1);
    assert_eq!(s.value(DVec3::ZERO), -0.6);
    assert!((s.value(DVec3::new(1.0, 0.0, 0.0)) - 0.4).abs() < 1e-15);
}

#[test]
fn gyroid_sphere_field_is_the_formula_over_thirty() {
    let s = gyroid_sphere();
    assert_eq!(s.node_count(), 4);
    s.validate().expect("valid");
    let p = s.compile();
    let mut rng = SplitMix64::new(3);
    for _ in 0..2000 {
        let q = DVec3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        );
        let want = gyroid_formula(q) / GYROID_SCALE;
        assert!((p.value(q) - want).abs() < 1e-12, "{q}");
    }
}

#[test]
fn gyroid_sphere_batch_values_match_in_single_precision() {
    let p = gyroid_sphere().compile();
    let pts = lattice_points(&Aabb::centered(DVec3::ONE), 3000);
    let mut out = vec![0.0f32; pts.len()];
    p.eval_many(&pts.x, &pts.y, &pts.z, &mut out, &mut BatchScratch::new(&p));
    for (i, v) in out.iter().enumerate() {
        let q = DVec3::new(pts.x[i] as f64, pts.y[i] as f64, pts.z[i] as f64);
        let want = gyroid_formula(q) / GYROID_SCALE;
        assert!((*v as f64 - want).abs() < 1e-4, "{q}: {v} vs {want}");
    }
}

#[test]
fn menger_counts_and_closed_forms() {
    assert_eq!(menger_bar_count(4), 2460);
    assert_eq!(
        (0..=4).map(menger_bar_count).collect::<Vec<_>>(),
        [0, 3, 30, 273, 2460]
    );
    assert_eq!(
        (0..=4).map(menger_genus).collect::<Vec<_>>(),
        [0, 5, 81, 1409, 26433]
    );
    assert!((menger_volume(4) - 0.301068).abs() < 1e-6);
    let m = menger(4);
    assert_eq!(m.children().len(), 1 + 2460);
    assert_eq!(m.node_count(), 2 + 2 * 2460);
    assert_eq!(m.compile().leaf_count(), 1 + 2460);
    assert_eq!(menger(0), Solid::difference_all(Solid::cube(1.0), []));
}

/// Inside the level-`level` sponge by its definition: no level where two coordinates have the
/// middle ternary digit; `None` within `margin` of a digit boundary or of the cube's faces
/// (points are drawn inside the cube).
fn sponge_contains(p: DVec3, level: u32, margin: f64) -> Option<bool> {
    let u = p + DVec3::splat(0.5);
    if u.min_element() < margin || u.max_element() > 1.0 - margin {
        return None;
    }
    let mut removed = false;
    for k in 1..=level {
        let scale = 3f64.powi(k as i32);
        let mut middles = 0;
        for a in 0..3 {
            let t = u[a] * scale;
            let frac = t - t.floor();
            if frac.min(1.0 - frac) * 3f64.powi(-(k as i32)) < margin {
                return None;
            }
            if t.floor() as i64 % 3 == 1 {
                middles += 1;
            }
        }
        removed |= middles >= 2;
    }
    Some(!removed)
}

#[test]
fn menger_field_sign_matches_the_ternary_definition() {
    let p = menger(3).compile();
    let mut rng = SplitMix64::new(27);
    let mut checked = 0;
    for _ in 0..20_000 {
        let q = DVec3::new(
            rng.range(-0.5, 0.5),
            rng.range(-0.5, 0.5),
            rng.range(-0.5, 0.5),
        );
        if let Some(inside) = sponge_contains(q, 3, 1e-6) {
            assert_eq!(p.value(q) < 0.0, inside, "{q}");
            checked += 1;
        }
    }
    assert!(checked > 19_000);
}

#[test]
fn many_has_the_benchmark_size() {
    let m = many(8456, MANY_DEFAULT_SEED);
    assert_eq!(m.node_count(), 2 * 8456 + 2);
    let (union, boxes) = m.children().split_first().expect("children");
    assert_eq!(union.children().len(), 4228);
    assert_eq!(boxes.len(), 4228);
    let p = m.compile();
    assert_eq!(p.leaf_count(), 8456);
    assert!(p.len() > 8456, "{} instructions", p.len());
    let b = m.bbox();
    assert!(b.min.min_element() >= -0.95 - 1e-12 && b.max.max_element() <= 0.95 + 1e-12);
}

#[test]
fn many_is_deterministic_and_seeded() {
    assert_eq!(many(100, 1), many(100, 1));
    assert_ne!(many(100, 1), many(100, 2));
    for count in [2, 3, 9, 100] {
        let m = many(count, 5);
        assert_eq!(m.node_count(), 2 * count + 2);
        let b = m.bbox();
        assert!(b.min.min_element() >= -0.95 - 1e-12 && b.max.max_element() <= 0.95 + 1e-12);
    }
}

#[test]
fn names_resolve() {
    for name in BENCH_MODELS {
        let m = Model::by_name(name).expect(name);
        m.solid.validate().expect("valid");
        assert!(!m.default_resolutions.is_empty());
        let b = m.solid.bbox().intersection(&m.domain);
        assert!(m.domain.contains(b.min) && m.domain.contains(b.max));
    }
    assert_eq!(Model::by_name("menger-2").expect("menger").genus, Some(81));
    assert!(matches!(
        Model::by_name("cube"),
        Err(ModelError::Unknown(_))
    ));
    for bad in ["menger-9", "menger-x", "many-1", "many-"] {
        assert!(
            matches!(Model::by_name(bad), Err(ModelError::BadParameter { .. })),
            "{bad}"
        );
    }
}

#[test]
fn splitmix_matches_the_reference_sequence() {
    let mut r = SplitMix64::new(0);
    assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
    let x = SplitMix64::new(9).next_f64();
    assert!((0.0..1.0).contains(&x));
}

#[test]
fn workloads_are_inside_their_domain() {
    let d = Aabb::centered(DVec3::ONE);
    let pts = lattice_points(&d, 1000);
    assert_eq!(pts.len(), 1000);
    assert!(
        pts.x
            .iter()
            .chain(&pts.y)
            .chain(&pts.z)
            .all(|v| v.abs() < 1.0)
    );
    let boxes = octree_boxes(&d, 500, 1);
    assert_eq!(boxes, octree_boxes(&d, 500, 1));
    for b in &boxes {
        assert!(d.contains(b.min) && d.contains(b.max) && !b.is_empty());
    }
}

/// Every directed edge used once and its opposite present: closed and consistently oriented.
fn closed_oriented(m: &crate::IndexedMesh) -> bool {
    let mut directed: Vec<(u32, u32)> = m
        .triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .collect();
    directed.sort_unstable();
    let unique = directed.windows(2).all(|w| w[0] != w[1]);
    unique
        && directed
            .iter()
            .all(|&(a, b)| directed.binary_search(&(b, a)).is_ok())
}

#[test]
fn menger_mesh_matches_its_closed_forms() {
    for level in 0..=3 {
        let m = menger_mesh(level).expect("small grid");
        assert!(closed_oriented(&m), "level {level}");
        let (v, e, f) = menger_mesh_counts(level);
        let edges = 3 * m.triangles.len() / 2;
        assert_eq!(
            (
                m.positions.len() as u64,
                edges as u64,
                m.triangles.len() as u64
            ),
            (v, e, f),
            "level {level}"
        );
        let (mut volume, mut area) = (0.0, 0.0);
        for t in 0..m.triangle_count() {
            let [a, b, c] = m.triangle_positions(t);
            volume += a.dot(b.cross(c)) / 6.0;
            area += (b - a).cross(c - a).length() / 2.0;
        }
        assert!((volume - menger_volume(level)).abs() < 1e-12, "{volume}");
        assert!((area - menger_area(level)).abs() < 1e-11, "{area}");
        let kept = menger_voxels(level).expect("grid").filled_count();
        assert_eq!(kept, 20usize.pow(level));
    }
    assert_eq!(menger_square_count(1), 72);
    assert_eq!(menger_mesh_counts(4), (283_520, 1_009_152, 672_768));
}

#[test]
fn menger_keeps_agrees_with_the_tree() {
    let p = menger(2).compile();
    for x in 0..9 {
        for y in 0..9 {
            for z in 0..9 {
                let c =
                    DVec3::new(x as f64, y as f64, z as f64) / 9.0 - DVec3::splat(0.5 - 1.0 / 18.0);
                assert_eq!(p.value(c) < 0.0, menger_keeps(2, x, y, z), "{x} {y} {z}");
            }
        }
    }
}
