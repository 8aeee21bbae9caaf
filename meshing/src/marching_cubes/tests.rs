//! Exhaustive and randomised marching-cubes tests on sign patterns, plus whole-path checks.
//!
//! Beyond closed / oriented / manifold / non-degenerate, each test checks the number of shells
//! against digital topology: samples of one side connect through grid edges, and the two samples
//! of one side on a diagonal of an ambiguous grid square connect through that square exactly when
//! the asymptotic decider says their side holds the saddle (inside when joined, outside when not).
//! Each surface separates two such components and they form a tree, so the surface has (inside
//! components + outside components − 1) shells.

use super::*;
use crate::TopologyReport;
use glam::DVec3;

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn spec(n: usize) -> GridSpec {
    GridSpec {
        origin: DVec3::ZERO,
        cell: 1.0,
        cells: [n, n, n],
    }
}

/// Components of samples with `inside(v) == want`, connected through grid edges and through the
/// diagonals of ambiguous squares their side wins by the decider. Flood fill with a work list.
fn components(g: &SampleGrid, want: bool) -> usize {
    let [sx, sy, sz] = g.spec.samples();
    let mut seen = vec![false; g.values.len()];
    let mut count = 0;
    let mut offsets = Vec::new();
    for d in [[-1i64, 0, 0], [0, -1, 0], [0, 0, -1]] {
        offsets.push(d);
        offsets.push(d.map(|x| -x));
    }
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        for (u, v) in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
            let mut d = [0i64; 3];
            d[a] = u;
            d[b] = v;
            offsets.push(d);
        }
    }
    let value = |p: [i64; 3]| g.at(p[0] as usize, p[1] as usize, p[2] as usize);
    for start in 0..g.values.len() {
        if seen[start] || inside(g.values[start]) != want {
            continue;
        }
        count += 1;
        seen[start] = true;
        let mut stack = vec![start];
        while let Some(s) = stack.pop() {
            let here = [
                (s % sx) as i64,
                ((s / sx) % sy) as i64,
                (s / (sx * sy)) as i64,
            ];
            for d in &offsets {
                let p = [0, 1, 2].map(|a| here[a] + d[a]);
                if p.iter()
                    .zip([sx, sy, sz])
                    .any(|(&c, n)| c < 0 || c >= n as i64)
                {
                    continue;
                }
                let n = g.spec.index(p[0] as usize, p[1] as usize, p[2] as usize);
                if seen[n] || inside(g.values[n]) != want {
                    continue;
                }
                if d.iter().filter(|&&x| x != 0).count() == 2 {
                    // The other diagonal of the square.
                    let axes: Vec<usize> = (0..3).filter(|&a| d[a] != 0).collect();
                    let (mut q, mut r) = (here, here);
                    q[axes[0]] += d[axes[0]];
                    r[axes[1]] += d[axes[1]];
                    let (vq, vr) = (value(q), value(r));
                    if inside(vq) == want || inside(vr) == want {
                        continue; // not ambiguous: connected through edges if at all
                    }
                    let (va, vb) = (g.values[s], g.values[n]);
                    let joined = if want {
                        table::face_joined(va, vb, vq, vr)
                    } else {
                        !table::face_joined(vq, vr, va, vb)
                    };
                    if !joined {
                        continue;
                    }
                }
                seen[n] = true;
                stack.push(n);
            }
        }
    }
    count
}

/// Cells of the dense samples whose configuration joins a face, and cells with a centre vertex.
pub(crate) fn joined_and_centre_cells(g: &SampleGrid) -> (usize, usize) {
    let t = table::case_table();
    let (mut joined, mut centres) = (0, 0);
    let [cx, cy, cz] = g.spec.cells;
    for k in 0..cz {
        for j in 0..cy {
            for i in 0..cx {
                let v = |c: u8| {
                    let c = usize::from(c);
                    g.at(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1))
                };
                let mask = (0..8u8)
                    .filter(|&c| inside(v(c)))
                    .fold(0, |m, c| m | 1 << c);
                let config = table::cell_config(mask, v);
                joined += usize::from(config >= 256);
                centres += usize::from(t.centre_loop[config] != table::NO_CENTRE);
            }
        }
    }
    (joined, centres)
}

fn check(g: &SampleGrid, what: &str) -> TopologyReport {
    let mesh = mesh_samples(g);
    let r = TopologyReport::of(&mesh);
    if components(g, true) == 0 {
        assert_eq!(r.faces, 0, "{what}: no inside sample, no surface");
        return r;
    }
    assert!(r.closed && r.manifold && r.oriented, "{what}: {r:?}");
    assert_eq!(r.degenerate_faces, 0, "{what}");
    assert_eq!(r.unreferenced_vertices, 0, "{what}");
    let expected = components(g, true) + components(g, false) - 1;
    assert_eq!(r.shells, expected, "{what}: shells");
    if r.faces > 0 {
        assert!(r.volume > 0.0, "{what}: outward orientation");
    }
    r
}

#[test]
fn all_256_patterns_alone_are_closed_spheres() {
    for mask in 0..256usize {
        let mut values = vec![1.0f32; 64];
        let g = spec(3);
        for c in 0..8 {
            let (i, j, k) = (1 + (c & 1), 1 + (c >> 1 & 1), 1 + (c >> 2 & 1));
            let v = 0.2 + 0.1 * c as f32;
            values[g.index(i, j, k)] = if mask >> c & 1 == 1 { -v } else { v };
        }
        let grid = SampleGrid::from_values(g, values).unwrap();
        let r = check(&grid, &format!("mask {mask:#010b}"));
        if mask == 0 {
            continue;
        }
        // No handle can form in one cell: every shell is a sphere.
        assert_eq!(
            r.euler_characteristic,
            2 * r.shells as i64,
            "mask {mask:#010b}"
        );
        assert_eq!(r.genus, Some(0));
    }
}

#[test]
fn ten_thousand_random_neighbourhoods_are_closed_manifolds() {
    let mut rng = Rng(0x5eed_1234_abcd_0001);
    let (mut joined, mut centres) = (0, 0);
    for case in 0..10_000 {
        let g = spec(5);
        let mut values = vec![1.0f32; g.sample_count()];
        for k in 1..5 {
            for j in 1..5 {
                for i in 1..5 {
                    let r = rng.unit();
                    values[g.index(i, j, k)] = if r < 0.04 {
                        0.0 // exact zeros follow the fixed rule (outside)
                    } else {
                        let m = (0.01 + rng.unit()) as f32;
                        if rng.next() & 1 == 0 { -m } else { m }
                    };
                }
            }
        }
        let grid = SampleGrid::from_values(g, values).unwrap();
        let r = check(&grid, &format!("case {case}"));
        assert_eq!(r.euler_characteristic % 2, 0);
        let (j, c) = joined_and_centre_cells(&grid);
        (joined, centres) = (joined + j, centres + c);
    }
    assert!(
        joined > 1000 && centres > 100,
        "joined {joined}, centres {centres}"
    );
}

#[test]
fn zeros_follow_one_rule_and_never_collapse_triangles() {
    // A plane through grid samples: every sample on it is exactly zero.
    let g = spec(6);
    let f = |p: DVec3| p.z - 3.0;
    let mesh = mesh_field(
        &|p: DVec3| f(p).max((p - DVec3::splat(3.0)).abs().max_element() - 2.0),
        g,
    );
    let r = TopologyReport::of(&mesh);
    assert!(
        r.closed && r.manifold && r.oriented && r.degenerate_faces == 0,
        "{r:?}"
    );
    // Zero counts as outside, so the slab is z < 3 (less a margin of 1e-4 cells).
    assert!((r.bbox[1][2] - 3.0).abs() < 2e-4, "{:?}", r.bbox);
}

fn sphere_grid() -> (GridSpec, impl Fn(DVec3) -> f64 + Sync) {
    let b = solidkit_kernel::Aabb::centered(DVec3::splat(1.0));
    (GridSpec::for_bounds(&b, 64).unwrap(), |p: DVec3| {
        p.length() - 1.0
    })
}

#[test]
fn sphere_volume_and_area_converge() {
    let (g, f) = sphere_grid();
    let r = TopologyReport::of(&mesh_field(&f, g));
    assert!(r.closed && r.manifold && r.oriented && r.shells == 1 && r.euler_characteristic == 2);
    let v = 4.0 / 3.0 * std::f64::consts::PI;
    assert!((r.volume - v).abs() / v < 0.01, "volume {}", r.volume);
    let a = 4.0 * std::f64::consts::PI;
    assert!((r.area - a).abs() / a < 0.02, "area {}", r.area);
}

#[test]
fn output_does_not_depend_on_thread_count() {
    let (g, f) = sphere_grid();
    let run = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| mesh_field(&f, g))
    };
    assert_eq!(run(1), run(3));
}

#[test]
fn grid_covers_bounds_with_one_cell_of_padding() {
    let b = solidkit_kernel::Aabb::new(DVec3::new(-1.0, 0.0, 2.0), DVec3::new(3.0, 1.0, 2.5));
    let g = GridSpec::for_bounds(&b, 40).unwrap();
    assert_eq!(g.cell, 0.1);
    assert_eq!(g.cells, [42, 12, 7]);
    let max = g.point(g.cells[0], g.cells[1], g.cells[2]);
    assert!(g.origin.cmple(b.min - DVec3::splat(0.1 - 1e-9)).all());
    assert!(max.cmpge(b.max + DVec3::splat(0.1 - 1e-9)).all());
    assert!(GridSpec::for_bounds(&solidkit_kernel::Aabb::infinite(), 10).is_err());
    assert!(GridSpec::for_bounds(&b, 0).is_err());
}

#[test]
fn noise_band_snaps_to_zero_and_scales_with_the_coordinates() {
    use super::{NOISE, snap_noise};
    // A polytope vertex evaluated at its f32-rounded position: a sign by chance, now zero.
    assert_eq!(snap_noise(0.57735, 0.57735, 0.57735, -1e-8), 0.0);
    assert_eq!(snap_noise(0.0, 0.0, 0.0, NOISE * 0.5), 0.0);
    // Real values keep their sign, and the band grows with the coordinates' magnitude.
    assert_eq!(snap_noise(0.0, 0.0, 0.0, -2.0 * NOISE), -2.0 * NOISE);
    assert_eq!(snap_noise(0.0, -100.0, 0.0, -50.0 * NOISE), 0.0);
    assert_eq!(snap_noise(0.0, -100.0, 0.0, -1e-3), -1e-3);
}
