//! Acceptance of height fields (issue 5): a Bézier height field and a 16-bit PNG height map meshed
//! at 128³ are closed genus-0 manifolds with volumes within 1% of their exact integrals, and the
//! parametric tessellations (sphere, ellipsoid, capsule, torus, height-field solid) are closed
//! oriented manifolds of the right genus whose volumes converge to the exact values.

use glam::{DVec2, DVec3};
use solidkit_kernel::primitive::heightfield::{
    HeightField, HeightGrid, HeightSource, Interpolation, load_png,
};
use solidkit_kernel::tessellate::{self, Tessellation};
use solidkit_kernel::{IndexedMesh, Primitive, Solid, json};
use solidkit_meshing::TopologyReport;
use solidkit_meshing::io::FileMeshResolver;
use solidkit_tests::{fixture, mesh, rel_err};
use std::f64::consts::PI;
use std::sync::Arc;

const RESOLUTION: usize = 128;

fn bezier_field() -> HeightField {
    let rows = vec![
        vec![0.5, 0.8, 0.6, 0.7],
        vec![0.9, 1.6, 0.7, 0.5],
        vec![0.6, 1.1, 1.3, 0.8],
    ];
    let grid = HeightGrid::from_rows(&rows).unwrap();
    HeightField::new(
        DVec2::new(-1.0, 0.0),
        DVec2::new(1.0, 1.5),
        0.1,
        HeightSource::Bezier(grid),
    )
    .unwrap()
}

fn report(hf: HeightField) -> TopologyReport {
    mesh(
        &Solid::primitive(Primitive::HeightField(Arc::new(hf))),
        RESOLUTION,
    )
    .1
}

#[test]
fn bezier_height_field_solid() {
    let hf = bezier_field();
    let g = hf.source().grid();
    // ∫∫ h = area × mean control height (each Bernstein polynomial integrates to 1/(n + 1)).
    let mean = g.values().iter().sum::<f64>() / g.values().len() as f64;
    let exact = 2.0 * 1.5 * (mean - 0.1);
    let r = report(hf);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(0)));
    eprintln!(
        "bezier: volume {} vs exact {exact} ({:.3}%)",
        r.volume,
        100.0 * rel_err(r.volume, exact)
    );
    assert!(
        rel_err(r.volume, exact) < 0.01,
        "volume {} vs {exact}",
        r.volume
    );
}

#[test]
fn png_height_map_solid() {
    let path = fixture("heightfields/bump16.png");
    // The path is relative to the tree's folder, as a tree file beside the PNG writes it.
    let resolver = FileMeshResolver::new(fixture("heightfields"));
    let text = r#"{"type": "heightfield", "min": [0, 0], "max": [2, 2], "base": 0,
            "png": "bump16.png", "heights": [0.1, 0.9]}"#;
    let solid = json::from_str_with(text, &resolver).unwrap();
    // Exact volume of the bilinear interpolant: trapezoid weights on the decoded samples.
    let g = load_png(&path).unwrap();
    let (nx, ny) = (g.nx(), g.ny());
    let mut sum = 0.0;
    for j in 0..ny {
        for i in 0..nx {
            let w = |k: usize, n: usize| if k == 0 || k == n - 1 { 0.5 } else { 1.0 };
            sum += w(i, nx) * w(j, ny) * (0.1 + 0.8 * g.get(i, j));
        }
    }
    let exact = sum * (2.0 / (nx - 1) as f64) * (2.0 / (ny - 1) as f64);
    let (_, r) = mesh(&solid, RESOLUTION);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(0)));
    eprintln!(
        "png: volume {} vs exact {exact} ({:.3}%)",
        r.volume,
        100.0 * rel_err(r.volume, exact)
    );
    assert!(
        rel_err(r.volume, exact) < 0.01,
        "volume {} vs {exact}",
        r.volume
    );
    // The PNG node writes its path back and reads to the same solid.
    assert_eq!(
        json::from_str_with(&json::to_string(&solid), &resolver).unwrap(),
        solid
    );
}

#[test]
fn bicubic_samples_round_trip_through_json() {
    let text = r#"{"type": "heightfield", "min": [0, 0], "max": [1, 2], "base": -0.5,
        "samples": [[0, 0.5, 0.2], [0.3, 0.9, 0.1]], "interpolation": "bicubic"}"#;
    let s = json::from_str(text).unwrap();
    assert_eq!(s, json::from_str(&json::to_string(&s)).unwrap());
    let bez = r#"{"type": "heightfield", "min": [0, 0], "max": [1, 1], "base": 0,
        "bezier": [[1, 2], [1, 3]]}"#;
    let s = json::from_str(bez).unwrap();
    assert_eq!(s, json::from_str(&json::to_string(&s)).unwrap());
    let e = json::from_str(
        r#"{"type": "heightfield", "min": [0, 0], "max": [1, 1], "base": 0, "samples": [[1, 2], [1]]}"#,
    )
    .unwrap_err();
    assert!(e.to_string().contains("samples"), "{e}");
    let e = json::from_str(
        r#"{"type": "heightfield", "min": [0, 0], "max": [1, 1], "base": 5, "bezier": [[1, 2], [1, 3]]}"#,
    )
    .unwrap_err();
    assert!(e.to_string().contains("base"), "{e}");
}

fn closed(t: &Tessellation, genus: i64) -> f64 {
    let r = TopologyReport::of(&t.mesh);
    assert!(r.is_closed_manifold(), "{r:?}");
    assert_eq!((r.shells, r.genus), (1, Some(genus)));
    assert_eq!(r.degenerate_faces, 0);
    r.volume
}

/// Volume errors of a sequence of refinements: each at most half the previous, the last below
/// `tol` relative.
fn converges(volumes: &[f64], exact: f64, tol: f64) {
    for w in volumes.windows(2) {
        assert!(
            (w[1] - exact).abs() < 0.5 * (w[0] - exact).abs(),
            "{volumes:?} vs {exact}"
        );
    }
    assert!(
        rel_err(*volumes.last().unwrap(), exact) < tol,
        "{volumes:?} vs {exact}"
    );
}

#[test]
fn parametric_tessellations_are_closed_and_converge() {
    let sizes = [(17, 9), (33, 17), (65, 33), (129, 65)];
    let sphere: Vec<f64> = sizes
        .iter()
        .map(|&(u, v)| closed(&tessellate::sphere(0.8, u, v).unwrap(), 0))
        .collect();
    converges(&sphere, 4.0 / 3.0 * PI * 0.512, 2e-3);
    let radii = DVec3::new(1.0, 0.5, 0.7);
    let ellipsoid: Vec<f64> = sizes
        .iter()
        .map(|&(u, v)| closed(&tessellate::ellipsoid(radii, u, v).unwrap(), 0))
        .collect();
    converges(&ellipsoid, 4.0 / 3.0 * PI * 0.35, 2e-3);
    let capsule: Vec<f64> = sizes
        .iter()
        .map(|&(u, v)| closed(&tessellate::capsule(0.4, 1.0, u, v).unwrap(), 0))
        .collect();
    converges(&capsule, PI * 0.16 + 4.0 / 3.0 * PI * 0.064, 2e-3);
    let torus: Vec<f64> = sizes
        .iter()
        .map(|&(u, v)| closed(&tessellate::torus(1.0, 0.25, u, v).unwrap(), 1))
        .collect();
    converges(&torus, 2.0 * PI * PI * 0.0625, 5e-3);
    let hf = bezier_field();
    let g = hf.source().grid();
    let mean = g.values().iter().sum::<f64>() / g.values().len() as f64;
    let field: Vec<f64> = [5, 9, 17, 33, 65]
        .iter()
        .map(|&n| closed(&tessellate::heightfield(&hf, n).unwrap(), 0))
        .collect();
    converges(&field, 3.0 * (mean - 0.1), 1e-3);
}

#[test]
fn meshed_height_field_matches_the_exact_tessellation() {
    // Marching cubes and the exact tessellation of the same solid agree on volume and area.
    let hf = bezier_field();
    let exact: IndexedMesh = tessellate::heightfield(&hf, 257).unwrap().mesh;
    let t = TopologyReport::of(&exact);
    let r = report(hf);
    assert!(
        rel_err(r.volume, t.volume) < 0.005,
        "{} vs {}",
        r.volume,
        t.volume
    );
    assert!(rel_err(r.area, t.area) < 0.03, "{} vs {}", r.area, t.area);
    let bicubic = HeightSource::Samples {
        grid: HeightGrid::new(3, 3, vec![0.3, 0.5, 0.3, 0.5, 1.0, 0.5, 0.3, 0.5, 0.3]).unwrap(),
        interpolation: Interpolation::Bicubic,
    };
    let dome = HeightField::new(DVec2::ZERO, DVec2::ONE, 0.0, bicubic).unwrap();
    let r = report(dome.clone());
    assert!(r.is_closed_manifold() && r.genus == Some(0), "{r:?}");
    let t = TopologyReport::of(&tessellate::heightfield(&dome, 257).unwrap().mesh);
    assert!(
        rel_err(r.volume, t.volume) < 0.01,
        "{} vs {}",
        r.volume,
        t.volume
    );
}
