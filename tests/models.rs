//! The benchmark models meshed: exact volume and genus of small Menger sponges, closed manifold
//! meshes of the others, and the `fixtures/bench/` trees equal to the models built in code.
//! No test here depends on time.

use glam::DVec3;
use solidkit_kernel::models::{self, Model, menger, menger_genus, menger_volume};
use solidkit_kernel::{Aabb, Solid, json};
use solidkit_meshing::TopologyReport;
use solidkit_meshing::pipeline::{Domain, MeshOptions, mesh_solid};
use solidkit_tests::{fixture, rel_err};

/// Meshes `solid` with `n` cells along the longest side of `domain` (the benchmark convention).
fn mesh_over(solid: &Solid, domain: &Aabb, n: usize) -> TopologyReport {
    let options = MeshOptions::new(n)
        .domain(Domain::Covering(*domain))
        .no_refinement();
    let mesh = mesh_solid(solid, &options).expect("mesh").mesh;
    let r = TopologyReport::of(&mesh);
    assert_eq!(r.self_intersections, Some(0), "{:?}", r.examples);
    r
}

fn menger_domain() -> Aabb {
    Aabb::centered(DVec3::splat(0.5 + models::MENGER_PAD))
}

#[test]
fn menger_levels_one_and_two_have_exact_genus_and_volume() {
    // 120 cells over 1.0625: the smallest level-2 tunnel (1/9 wide) spans about 12 cells.
    for level in [1, 2] {
        let r = mesh_over(&menger(level), &menger_domain(), 120);
        assert!(r.closed && r.manifold && r.oriented, "level {level}: {r:?}");
        assert_eq!(r.shells, 1, "level {level}");
        assert_eq!(r.genus, Some(menger_genus(level)), "level {level}");
        let err = rel_err(r.volume, menger_volume(level));
        assert!(err < 0.01, "level {level}: volume {} ({err})", r.volume);
    }
}

#[test]
fn menger_level_zero_is_the_cube() {
    let r = mesh_over(&menger(0), &menger_domain(), 32);
    assert!(r.closed && r.manifold);
    assert_eq!(r.genus, Some(0));
    assert!(rel_err(r.volume, 1.0) < 0.01);
}

#[test]
fn sphere_and_gyroid_sphere_mesh_closed_and_manifold() {
    let sphere = Model::by_name("sphere").expect("model");
    let r = mesh_over(&sphere.solid, &sphere.domain, 64);
    assert!(r.closed && r.manifold && r.oriented);
    assert_eq!(r.genus, sphere.genus);
    assert!(rel_err(r.volume, sphere.volume.expect("known")) < 0.01);

    let gyroid = Model::by_name("gyroid-sphere").expect("model");
    let r = mesh_over(&gyroid.solid, &gyroid.domain, 96);
    assert!(r.closed && r.manifold && r.oriented, "{r:?}");
    assert!(r.faces > 0 && r.genus.is_some());
}

#[test]
fn a_small_many_meshes_closed_and_manifold() {
    let solid = models::many(300, models::MANY_DEFAULT_SEED);
    let r = mesh_over(&solid, &Aabb::centered(DVec3::ONE), 96);
    assert!(r.closed && r.manifold && r.oriented, "{r:?}");
    assert!(r.shells >= 1);
}

#[test]
fn bench_fixtures_are_the_models() {
    for (file, name) in [
        ("bench/sphere.json", "sphere"),
        ("bench/gyroid-sphere.json", "gyroid-sphere"),
        ("bench/menger-2.json", "menger-2"),
    ] {
        let text = std::fs::read_to_string(fixture(file)).expect("fixture");
        let tree = json::from_str(&text).expect("parses");
        assert_eq!(tree, Model::by_name(name).expect("model").solid, "{file}");
    }
}
