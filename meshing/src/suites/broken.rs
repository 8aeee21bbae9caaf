//! The `broken` suite: small meshes with known defects, for testing mesh checkers. Every mesh is
//! built from unit cubes, an octahedron and a tetrahedron with dyadic coordinates (exact in
//! `f32`, so STL keeps them), and distinct vertices have distinct positions, so every format
//! (STL welds equal positions) stores the same topology.
//!
//! Each solid lists the defects put in ([`Defect`]) and what `solidkit check --json` must report
//! ([`ExpectedCheck`]), derived by hand from the construction:
//! - `hole`: a cube missing one triangle: 3 boundary edges;
//! - `flipped_face`: an octahedron with one triangle reversed: its 3 edges are traversed the same
//!   way by both neighbours (3 inconsistent edges);
//! - `non_manifold_edge`: two cubes sharing only an edge (4 triangles on it);
//! - `non_manifold_vertex`: two cubes sharing only a corner (two fans there);
//! - `duplicate_face`: a cube with one triangle repeated: its 3 edges have 3 triangles each, and
//!   the copy overlaps the original (1 self-intersecting pair);
//! - `self_intersection`: a cube and a tetrahedron as two closed shells, the tetrahedron's apex
//!   poking through one top triangle of the cube: 3 pairs of crossing triangles;
//! - `degenerate_faces`: a cube with one triangle split at the midpoint of an edge, closed by the
//!   zero-area triangle on that edge (still a closed manifold), plus a triangle with a repeated
//!   vertex index (left out of the topology). The two halves each share one vertex with the
//!   triangle across the split edge but touch it along half of that edge: 2 self-intersecting
//!   pairs, since triangles that meet beyond the vertices they share count (the zero-area triangle
//!   itself is skipped, as `solidkit check` does).

use super::GenSolid;
use super::truth::{Truth, TruthMethod};
use crate::IndexedMesh;
use glam::DVec3;
use serde::Serialize;
use serde_json::json;
use std::collections::HashMap;

/// A kind of defect.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DefectKind {
    /// Missing triangles (boundary edges).
    Hole,
    /// A triangle wound the wrong way.
    FlippedFace,
    /// An edge with more than two triangles.
    NonManifoldEdge,
    /// A vertex whose triangles form more than one fan.
    NonManifoldVertex,
    /// A triangle present twice.
    DuplicateFace,
    /// Triangles crossing each other.
    SelfIntersection,
    /// A triangle of zero area with three distinct, collinear corners (kept in the topology).
    CollinearFace,
    /// A triangle with a repeated vertex index (left out of the topology; also degenerate).
    RepeatedIndexFace,
}

/// One defect put into a mesh.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Defect {
    /// What kind.
    pub kind: DefectKind,
    /// How many of it.
    pub count: usize,
    /// Where and how it was made.
    pub detail: String,
}

/// What a checker must report for the mesh (keys of `solidkit check --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExpectedCheck {
    /// Referenced vertices.
    pub vertices: usize,
    /// Undirected edges.
    pub edges: usize,
    /// Usable triangles (not counting repeated-index ones).
    pub faces: usize,
    /// `V − E + F`.
    pub euler_characteristic: i64,
    /// Connected components (sharing a vertex connects).
    pub shells: usize,
    /// Edges with one triangle.
    pub boundary_edges: usize,
    /// Edges with more than two triangles.
    pub non_manifold_edges: usize,
    /// Vertices with more than one fan.
    pub non_manifold_vertices: usize,
    /// Two-triangle edges traversed the same way by both.
    pub inconsistent_edges: usize,
    /// Zero-area or repeated-index triangles.
    pub degenerate_faces: usize,
    /// Pairs of triangles that meet beyond the vertices they share (touching counts; duplicates
    /// count; zero-area triangles are skipped).
    pub self_intersections: usize,
    /// No boundary edges.
    pub closed: bool,
    /// No non-manifold edges or vertices.
    pub manifold: bool,
    /// No inconsistent edges.
    pub oriented: bool,
}

/// The defects of one mesh and the report they must produce.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Defects {
    /// The defects put in.
    pub put_in: Vec<Defect>,
    /// What `solidkit check` must report.
    pub expected: ExpectedCheck,
}

/// A mesh under construction; equal positions share one vertex.
#[derive(Default)]
struct Builder {
    mesh: IndexedMesh,
    ids: HashMap<[u64; 3], u32>,
}

impl Builder {
    fn vertex(&mut self, p: DVec3) -> u32 {
        let key = p.to_array().map(f64::to_bits);
        *self.ids.entry(key).or_insert_with(|| {
            self.mesh.positions.push(p);
            (self.mesh.positions.len() - 1) as u32
        })
    }

    fn triangle(&mut self, t: [DVec3; 3]) {
        let t = t.map(|p| self.vertex(p));
        self.mesh.triangles.push(t);
    }

    /// The 12 outward triangles of the unit cube with lowest corner `at` (corner `i` at
    /// `at + (i & 1, i >> 1 & 1, i >> 2)`; each face split along the diagonal from its first
    /// corner).
    fn cube(&mut self, at: DVec3) {
        for t in cube_triangles() {
            self.triangle(t.map(|i| at + corner(i)));
        }
    }
}

fn corner(i: u32) -> DVec3 {
    DVec3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2))
}

/// The cube's triangles as corner numbers, counter-clockwise from outside.
fn cube_triangles() -> Vec<[u32; 3]> {
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    quads
        .iter()
        .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
        .collect()
}

/// A closed oriented manifold's expected report with `shells`, `(V, E, F)`.
fn clean(shells: usize, (v, e, f): (usize, usize, usize)) -> ExpectedCheck {
    ExpectedCheck {
        vertices: v,
        edges: e,
        faces: f,
        euler_characteristic: v as i64 - e as i64 + f as i64,
        shells,
        boundary_edges: 0,
        non_manifold_edges: 0,
        non_manifold_vertices: 0,
        inconsistent_edges: 0,
        degenerate_faces: 0,
        self_intersections: 0,
        closed: true,
        manifold: true,
        oriented: true,
    }
}

fn defect(kind: DefectKind, count: usize, detail: &str) -> Defect {
    Defect {
        kind,
        count,
        detail: detail.to_owned(),
    }
}

fn broken(
    name: &str,
    description: &str,
    mesh: IndexedMesh,
    put_in: Vec<Defect>,
    expected: ExpectedCheck,
    genus: Option<i64>,
) -> GenSolid {
    let mut truth = Truth {
        shells: Some(expected.shells),
        euler_characteristic: Some(expected.euler_characteristic),
        vertices: Some(expected.vertices as u64),
        edges: Some(expected.edges as u64),
        faces: Some(expected.faces as u64),
        topology_method: Some(TruthMethod::Construction),
        genus,
        ..Truth::default()
    };
    if genus.is_none() {
        truth = truth.with_note("genus not defined: not every shell is a closed oriented manifold");
    }
    GenSolid {
        name: name.to_owned(),
        description: description.to_owned(),
        parameters: json!({}),
        mesh,
        truth,
        chord_error_bound: None,
        volume_tolerance: None,
        tree: None,
        defects: Some(Defects { put_in, expected }),
    }
}

/// The suite's meshes.
pub fn solids() -> Vec<GenSolid> {
    vec![
        hole(),
        flipped_face(),
        non_manifold_edge(),
        non_manifold_vertex(),
        duplicate_face(),
        self_intersection(),
        degenerate_faces(),
    ]
}

fn hole() -> GenSolid {
    let mut b = Builder::default();
    b.cube(DVec3::ZERO);
    b.mesh.triangles.pop();
    let mut e = clean(1, (8, 18, 11));
    e.boundary_edges = 3;
    e.closed = false;
    broken(
        "hole",
        "unit cube [0, 1]^3 missing its last triangle (on the face x = 1)",
        b.mesh,
        vec![defect(
            DefectKind::Hole,
            1,
            "one missing triangle: 3 boundary edges",
        )],
        e,
        None,
    )
}

fn flipped_face() -> GenSolid {
    let mut b = Builder::default();
    for s in 0..8u32 {
        let sign = |bit: u32| if s >> bit & 1 == 0 { 1.0 } else { -1.0 };
        let (x, y, z) = (DVec3::X * sign(0), DVec3::Y * sign(1), DVec3::Z * sign(2));
        let outward = sign(0) * sign(1) * sign(2) > 0.0;
        // The first face (the +x +y +z octant) is the flipped one.
        if outward == (s != 0) {
            b.triangle([x, y, z]);
        } else {
            b.triangle([x, z, y]);
        }
    }
    let mut e = clean(1, (6, 12, 8));
    e.inconsistent_edges = 3;
    e.oriented = false;
    broken(
        "flipped_face",
        "octahedron with vertices on the axes at distance 1, the face in the octant x, y, z > 0 reversed",
        b.mesh,
        vec![defect(
            DefectKind::FlippedFace,
            1,
            "triangle 0 wound inwards: its 3 edges are inconsistent",
        )],
        e,
        None,
    )
}

fn non_manifold_edge() -> GenSolid {
    let mut b = Builder::default();
    b.cube(DVec3::ZERO);
    b.cube(DVec3::new(1.0, 1.0, 0.0));
    let mut e = clean(1, (14, 35, 24));
    e.non_manifold_edges = 1;
    e.manifold = false;
    broken(
        "non_manifold_edge",
        "unit cubes at (0, 0, 0) and (1, 1, 0) sharing only the edge x = y = 1",
        b.mesh,
        vec![defect(
            DefectKind::NonManifoldEdge,
            1,
            "edge (1, 1, 0)-(1, 1, 1) has 4 triangles",
        )],
        e,
        None,
    )
}

fn non_manifold_vertex() -> GenSolid {
    let mut b = Builder::default();
    b.cube(DVec3::ZERO);
    b.cube(DVec3::ONE);
    let mut e = clean(1, (15, 36, 24));
    e.non_manifold_vertices = 1;
    e.manifold = false;
    broken(
        "non_manifold_vertex",
        "unit cubes at (0, 0, 0) and (1, 1, 1) sharing only the corner (1, 1, 1)",
        b.mesh,
        vec![defect(
            DefectKind::NonManifoldVertex,
            1,
            "vertex (1, 1, 1) has two fans",
        )],
        e,
        None,
    )
}

fn duplicate_face() -> GenSolid {
    let mut b = Builder::default();
    b.cube(DVec3::ZERO);
    let first = b.mesh.triangles[0];
    b.mesh.triangles.push(first);
    let mut e = clean(1, (8, 18, 13));
    e.non_manifold_edges = 3;
    e.self_intersections = 1;
    e.manifold = false;
    broken(
        "duplicate_face",
        "unit cube with its first triangle written twice (same winding)",
        b.mesh,
        vec![defect(
            DefectKind::DuplicateFace,
            1,
            "triangle 12 repeats triangle 0: its 3 edges have 3 triangles each and it overlaps triangle 0",
        )],
        e,
        None,
    )
}

fn self_intersection() -> GenSolid {
    let mut b = Builder::default();
    b.cube(DVec3::ZERO);
    let apex = DVec3::new(0.25, 0.75, 1.5);
    let [p, q, r] = [
        DVec3::new(0.125, 0.625, 0.5),
        DVec3::new(0.375, 0.625, 0.5),
        DVec3::new(0.25, 0.875, 0.5),
    ];
    b.triangle([p, r, q]);
    b.triangle([p, q, apex]);
    b.triangle([q, r, apex]);
    b.triangle([r, p, apex]);
    let mut e = clean(2, (12, 24, 16));
    e.self_intersections = 3;
    broken(
        "self_intersection",
        "unit cube and a tetrahedron (apex (0.25, 0.75, 1.5), base at z = 0.5) as two closed shells; the apex pokes through the cube's top",
        b.mesh,
        vec![defect(
            DefectKind::SelfIntersection,
            3,
            "the tetrahedron's 3 side triangles cross the cube's top triangle (0,0,1)-(1,1,1)-(0,1,1)",
        )],
        e,
        Some(0),
    )
}

fn degenerate_faces() -> GenSolid {
    let mut b = Builder::default();
    let tris = cube_triangles();
    // Triangle (4, 5, 7) = (a, b, c) with a = 7, b = 4, c = 5 shares the top diagonal 4-7 with
    // (4, 7, 6). Split it at the diagonal's midpoint m and close with the flat triangle (7, 4, m).
    let m = (corner(4) + corner(7)) * 0.5;
    for t in &tris {
        if *t == [4, 5, 7] {
            b.triangle([corner(7), m, corner(5)]);
            b.triangle([m, corner(4), corner(5)]);
            b.triangle([corner(7), corner(4), m]);
        } else {
            b.triangle(t.map(corner));
        }
    }
    let v0 = b.vertex(corner(0));
    let v1 = b.vertex(corner(1));
    b.mesh.triangles.push([v0, v0, v1]);
    let mut e = clean(1, (9, 21, 14));
    e.degenerate_faces = 2;
    e.self_intersections = 2;
    broken(
        "degenerate_faces",
        "unit cube whose top triangle (0,0,1)-(1,0,1)-(1,1,1) is split at the midpoint of its diagonal and closed by the zero-area triangle on the diagonal, plus one triangle with a repeated vertex index",
        b.mesh,
        vec![
            defect(
                DefectKind::CollinearFace,
                1,
                "zero-area triangle (1,1,1)-(0,0,1)-(0.5,0.5,1) (collinear corners; the mesh stays closed)",
            ),
            defect(
                DefectKind::RepeatedIndexFace,
                1,
                "triangle [0, 0, 1] with a repeated index (left out of the topology)",
            ),
        ],
        e,
        Some(0),
    )
}
