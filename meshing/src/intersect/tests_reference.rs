//! The fast path against the first implementation (`reference.rs`, kernel BVH broad phase): the
//! same count and the same examples on meshes with known self-intersections — the `broken`
//! suite of `solidkit gen`, random triangle soups with repeated triangles, and a tessellated
//! sphere with vertices pushed through it — for several example limits.

use glam::DVec3;
use solidkit_kernel::tessellate;

use super::reference::reference_self_intersections;
use super::self_intersections;
use crate::IndexedMesh;

/// Asserts the fast and reference results agree for a few limits; returns the count.
fn agree(mesh: &IndexedMesh, what: &str) -> usize {
    let mut count = None;
    for limit in [0, 8, 1000] {
        let fast = self_intersections(mesh, limit).unwrap();
        let reference = reference_self_intersections(mesh, limit).unwrap();
        assert_eq!(fast, reference, "{what}, limit {limit}");
        count = Some(fast.count);
    }
    count.unwrap_or(0)
}

/// (The broken suite is a generator: it exists with the `suites` feature, which `cargo test
/// --workspace` enables through the binary.)
#[cfg(feature = "suites")]
#[test]
fn broken_suite_agrees() {
    let mut with_some = 0;
    for solid in crate::suites::broken::solids() {
        let expected = solid
            .defects
            .as_ref()
            .map(|d| d.expected.self_intersections);
        let count = agree(&solid.mesh, &solid.name);
        assert_eq!(Some(count), expected, "{}", solid.name);
        with_some += usize::from(count > 0);
    }
    assert!(
        with_some >= 2,
        "the suite has meshes with self-intersections"
    );
}

/// A small deterministic generator (also for `fans.rs`).
pub(super) struct Lcg(pub(super) u64);

impl Lcg {
    /// The next state, all 64 bits.
    pub(super) fn bits(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0
    }

    /// The next number in `[0, 1)`.
    pub(super) fn unit(&mut self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn random_soups_with_copies_agree() {
    let mut rng = Lcg(99);
    for (n, pool) in [(50, 20), (400, 300), (1200, 3000)] {
        let positions: Vec<DVec3> = (0..pool)
            .map(|_| DVec3::new(rng.unit(), rng.unit(), rng.unit()))
            .collect();
        let mut triangles: Vec<[u32; 3]> = (0..n)
            .map(|_| [0, 1, 2].map(|_| (rng.unit() * pool as f64) as u32))
            .collect();
        // Copies in other vertex orders, and a few unusable triangles.
        for k in 0..n / 10 {
            let [a, b, c] = triangles[k * 7 % n];
            triangles.push([c, a, b]);
        }
        triangles.push([0, 0, 1]);
        triangles.push([0, 1, u32::MAX]);
        let mesh = IndexedMesh::new(positions, triangles);
        assert!(agree(&mesh, &format!("soup {n}")) > 0);
    }
}

#[test]
fn sphere_with_pushed_vertices_agrees() {
    let t = tessellate::sphere(1.0, 48, 25).unwrap().mesh;
    let mut mesh = IndexedMesh::new(t.positions, t.triangles);
    assert_eq!(agree(&mesh, "sphere"), 0);
    let len = mesh.positions.len();
    for k in [len / 3, len / 2, 2 * len / 3] {
        mesh.positions[k] *= -0.7;
    }
    assert!(agree(&mesh, "pushed sphere") > 0);
}
