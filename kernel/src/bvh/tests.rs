//! Tests of the triangle BVH: the layout (children after parents, exact boxes equal to the union
//! of their contents, leaves partitioning the slots, subtrees owning contiguous slots), nearest
//! points equal to brute force for several leaf sizes, overlap queries equal to brute force, and
//! degenerate inputs (empty, flat, a single point, coordinates beyond `f32`).

use super::*;
use crate::closest::closest_point_on_triangle;
use crate::primitive::conformance::Rng;

/// `n` small random triangles in `[-1, 1]³`, some degenerate (a repeated corner, collinear).
fn soup(rng: &mut Rng, n: usize) -> Vec<[DVec3; 3]> {
    (0..n)
        .map(|i| {
            let c = rng.vec(1.0);
            let t = [c + rng.vec(0.1), c + rng.vec(0.1), c + rng.vec(0.1)];
            match i % 37 {
                5 => [t[0], t[0], t[1]],
                11 => [t[0], t[1], t[0] * 0.5 + t[1] * 0.5],
                _ => t,
            }
        })
        .collect()
}

fn brute_nearest2(triangles: &[[DVec3; 3]], q: DVec3) -> f64 {
    triangles
        .iter()
        .map(|t| closest_point_on_triangle(q, *t).distance_squared(q))
        .fold(f64::INFINITY, f64::min)
}

fn box_of([a, b, c]: [DVec3; 3]) -> (DVec3, DVec3) {
    (a.min(b).min(c), a.max(b).max(c))
}

/// Checks every structural promise of the module docs.
fn check_layout(bvh: &TriangleBvh, input: &[[DVec3; 3]], leaf_size: u32) {
    let nodes = bvh.nodes();
    assert_eq!(bvh.len(), input.len());
    // The slot order is a permutation and the corners follow it.
    let mut seen = vec![false; input.len()];
    for slot in 0..bvh.len() {
        let i = bvh.slot_index(slot) as usize;
        assert!(!seen[i], "input {i} in two slots");
        seen[i] = true;
        assert_eq!(bvh.corners()[slot], input[i]);
    }
    // Children after parents, boxes exact, and each node's slots a contiguous run.
    let mut runs = vec![0..0; nodes.len()];
    for i in (0..nodes.len()).rev() {
        let node = nodes[i];
        let (lo, hi, run) = if node.is_leaf() {
            assert!(node.count <= leaf_size.max(1), "leaf of {}", node.count);
            let (lo, hi) = bvh.corners()[node.slots()]
                .iter()
                .map(|t| box_of(*t))
                .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), (a, b)| {
                    (l.min(a), h.max(b))
                });
            (lo, hi, node.slots())
        } else {
            let first = node.first as usize;
            assert!(first > i && first + 1 < nodes.len(), "children of {i}");
            let (a, b) = (&nodes[first], &nodes[first + 1]);
            let (ra, rb) = (runs[first].clone(), runs[first + 1].clone());
            let run = if ra.end == rb.start {
                ra.start..rb.end
            } else {
                assert_eq!(rb.end, ra.start, "subtree of {i} not contiguous");
                rb.start..ra.end
            };
            (a.min.min(b.min), a.max.max(b.max), run)
        };
        assert_eq!((node.min, node.max), (lo, hi), "box of node {i}");
        runs[i] = run;
    }
    assert_eq!(runs[0], 0..input.len());
    // The leaves partition the slots, in order.
    let mut next = 0;
    for leaf in bvh.leaves() {
        assert_eq!(leaf.start, next);
        assert!(leaf.end > leaf.start);
        next = leaf.end;
    }
    assert_eq!(next, input.len());
}

#[test]
fn layout_holds_for_every_leaf_size() {
    let mut rng = Rng::new(5);
    for leaf_size in [1, 2, 4, 8] {
        for n in [1, 2, 3, 10, 500] {
            let input = soup(&mut rng, n);
            let bvh = TriangleBvh::new(input.clone(), leaf_size).unwrap();
            check_layout(&bvh, &input, leaf_size);
            let (lo, hi) = input
                .iter()
                .flatten()
                .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), p| {
                    (l.min(*p), h.max(*p))
                });
            assert_eq!(bvh.bbox(), Aabb::new(lo, hi));
        }
    }
}

#[test]
fn nearest_equals_brute_force() {
    let mut rng = Rng::new(3);
    for leaf_size in [1, 4] {
        for n in [1, 2, 7, 300, 2000] {
            let input = soup(&mut rng, n);
            let bvh = TriangleBvh::new(input.clone(), leaf_size).unwrap();
            for k in 0..300 {
                // Near the triangles, on them, and far away.
                let q = match k % 3 {
                    0 => rng.vec(1.5),
                    1 => input[k % n][0] * 0.5 + input[k % n][1] * 0.5,
                    _ => rng.vec(50.0),
                };
                let got = bvh.nearest(q).unwrap();
                let want = brute_nearest2(&input, q);
                assert_eq!(got.distance2, want, "leaf {leaf_size} n={n} q={q}");
                // The reported slot holds a nearest triangle, and the point is on it.
                let t = input[bvh.slot_index(got.slot as usize) as usize];
                let p = closest_point_on_triangle(q, t);
                assert_eq!(p, got.point);
                assert_eq!(p.distance_squared(q), want);
            }
        }
    }
}

#[test]
fn overlap_finds_exactly_the_meeting_boxes() {
    let mut rng = Rng::new(17);
    let input = soup(&mut rng, 1500);
    for leaf_size in [1, 4] {
        let bvh = TriangleBvh::new(input.clone(), leaf_size).unwrap();
        for k in 0..200 {
            let c = rng.vec(1.2);
            let h = DVec3::new(rng.next(), rng.next(), rng.next()).abs() * 0.2;
            // Also a query box that is exactly a triangle's box (touching counts).
            let (lo, hi) = if k % 4 == 0 {
                box_of(input[k % input.len()])
            } else {
                (c - h, c + h)
            };
            let mut got: Vec<u32> = Vec::new();
            bvh.for_each_overlap(lo, hi, |slot| got.push(bvh.slot_index(slot)));
            got.sort_unstable();
            let want: Vec<u32> = (0..input.len() as u32)
                .filter(|&i| {
                    let (l, h) = box_of(input[i as usize]);
                    l.cmple(hi).all() && lo.cmple(h).all()
                })
                .collect();
            assert_eq!(got, want, "box {lo} {hi}");
            if k % 4 == 0 {
                assert!(got.contains(&((k % input.len()) as u32)));
            }
        }
    }
}

#[test]
fn an_empty_tree_answers_nothing() {
    let bvh = TriangleBvh::new(Vec::new(), 4).unwrap();
    assert!(bvh.is_empty() && bvh.nodes().is_empty());
    assert_eq!(bvh.nearest(DVec3::ONE), None);
    assert!(bvh.leaves().is_empty());
    assert!(bvh.bbox().is_empty());
    let mut calls = 0;
    bvh.for_each_overlap(DVec3::splat(-1e9), DVec3::splat(1e9), |_| calls += 1);
    assert_eq!(calls, 0);
}

#[test]
fn degenerate_extents_stay_exact() {
    let mut rng = Rng::new(23);
    // Flat: every triangle in the plane z = 0.25.
    let flat: Vec<[DVec3; 3]> = soup(&mut rng, 400)
        .into_iter()
        .map(|t| t.map(|p| DVec3::new(p.x, p.y, 0.25)))
        .collect();
    // A single point, many times.
    let point = vec![[DVec3::splat(0.5); 3]; 40];
    // Far beyond f32 (normalised coordinates keep the build working), and an extent that
    // overflows (everything is built at the origin: slower, still exact).
    let huge: Vec<[DVec3; 3]> = soup(&mut rng, 300)
        .into_iter()
        .map(|t| t.map(|p| p * 1e150))
        .collect();
    let mut overflow = soup(&mut rng, 100);
    overflow.push([DVec3::X * -1e308; 3]);
    overflow.push([DVec3::X * 1e308, DVec3::new(1e308, 1.0, 0.0), DVec3::Y]);
    for (input, scale) in [(flat, 1.0), (point, 1.0), (huge, 1e150), (overflow, 1.0)] {
        for leaf_size in [1, 4] {
            let bvh = TriangleBvh::new(input.clone(), leaf_size).unwrap();
            check_layout(&bvh, &input, leaf_size);
            for _ in 0..100 {
                let q = rng.vec(1.5) * scale;
                let got = bvh.nearest(q).unwrap().distance2;
                assert_eq!(got, brute_nearest2(&input, q), "q={q}");
            }
        }
    }
}

#[test]
fn a_query_inside_an_overlap_callback_gets_its_own_stack() {
    let mut rng = Rng::new(29);
    let input = soup(&mut rng, 300);
    let bvh = TriangleBvh::new(input.clone(), 4).unwrap();
    let (lo, hi) = (DVec3::splat(-0.3), DVec3::splat(0.3));
    let mut outer = 0;
    bvh.for_each_overlap(lo, hi, |slot| {
        outer += 1;
        let (l, h) = box_of(bvh.corners()[slot]);
        let mut inner = 0;
        bvh.for_each_overlap(l, h, |other| inner += usize::from(other == slot));
        assert_eq!(inner, 1, "a triangle's box meets itself once");
    });
    let want = input
        .iter()
        .filter(|t| {
            let (l, h) = box_of(**t);
            l.cmple(hi).all() && lo.cmple(h).all()
        })
        .count();
    assert_eq!(outer, want);
}

/// Many copies of a few triangles (obvhs alone is quadratic there): built over the distinct
/// boxes, the layout still holds for every leaf size, queries equal brute force, and 40 000
/// copies of one triangle build in well under a second.
#[test]
fn repeated_triangles_build_fast_and_answer_exactly() {
    let mut rng = Rng::new(9);
    let few = soup(&mut rng, 20);
    let mut input: Vec<[DVec3; 3]> = (0..3000).map(|k| few[(k * 7 + k / 13) % 20]).collect();
    input.extend(soup(&mut rng, 200));
    for leaf_size in [1, 2, 4, 8] {
        let bvh = TriangleBvh::new(input.clone(), leaf_size).unwrap();
        check_layout(&bvh, &input, leaf_size);
        for k in 0..100 {
            let q = if k % 2 == 0 {
                rng.vec(1.5)
            } else {
                input[k * 31][1]
            };
            assert_eq!(bvh.nearest(q).unwrap().distance2, brute_nearest2(&input, q));
            let (lo, hi) = (q - DVec3::splat(0.2), q + DVec3::splat(0.2));
            let mut got = Vec::new();
            bvh.for_each_overlap(lo, hi, |s| got.push(bvh.slot_index(s)));
            got.sort_unstable();
            let want: Vec<u32> = (0..input.len() as u32)
                .filter(|&i| {
                    let (a, b) = box_of(input[i as usize]);
                    a.cmple(hi).all() && lo.cmple(b).all()
                })
                .collect();
            assert_eq!(got, want, "leaf {leaf_size}");
        }
    }
    let one = vec![[DVec3::ZERO, DVec3::X, DVec3::Y]; 40_000];
    let start = std::time::Instant::now();
    let bvh = TriangleBvh::new(one.clone(), 1).unwrap();
    assert!(start.elapsed().as_secs_f64() < 1.0, "{:?}", start.elapsed());
    check_layout(&bvh, &one, 1);
}
