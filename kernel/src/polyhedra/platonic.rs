//! The five Platonic solids, centred at the origin, sized by circumradius or edge length.
//!
//! Vertices come from the classic coordinates (tetrahedron: alternate cube corners `(1, 1, 1)`,
//! `(1, −1, −1)`, …; cube `(±1, ±1, ±1)`; octahedron `(±1, 0, 0)` and permutations; icosahedron
//! `(0, ±1, ±φ)` cyclically; dodecahedron `(±1, ±1, ±1)` and `(0, ±1/φ, ±φ)` cyclically), scaled
//! to circumradius 1; the faces are found as the convex hull of those points. Each kind's unit
//! data (unit face normals, inradius, edge and bounding half extents at circumradius 1) is built
//! once per process.

use super::Polyhedron;
use super::PolyhedronError;
use super::hull::convex_faces;
use glam::DVec3;
use std::sync::OnceLock;

/// One of the five regular convex polyhedra.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PlatonicKind {
    /// 4 triangles (V 4, E 6, F 4).
    Tetrahedron,
    /// 6 squares (V 8, E 12, F 6).
    Cube,
    /// 8 triangles (V 6, E 12, F 8).
    Octahedron,
    /// 12 pentagons (V 20, E 30, F 12).
    Dodecahedron,
    /// 20 triangles (V 12, E 30, F 20).
    Icosahedron,
}

impl PlatonicKind {
    /// All five, in order of face count.
    pub const ALL: [PlatonicKind; 5] = [
        PlatonicKind::Tetrahedron,
        PlatonicKind::Cube,
        PlatonicKind::Octahedron,
        PlatonicKind::Dodecahedron,
        PlatonicKind::Icosahedron,
    ];

    /// The lower-case name used in the JSON tree format (`"icosahedron"`, …).
    pub fn name(self) -> &'static str {
        match self {
            PlatonicKind::Tetrahedron => "tetrahedron",
            PlatonicKind::Cube => "cube",
            PlatonicKind::Octahedron => "octahedron",
            PlatonicKind::Dodecahedron => "dodecahedron",
            PlatonicKind::Icosahedron => "icosahedron",
        }
    }

    /// The kind named `name` (as written by [`PlatonicKind::name`]).
    pub fn from_name(name: &str) -> Option<PlatonicKind> {
        PlatonicKind::ALL.into_iter().find(|k| k.name() == name)
    }

    /// The kind of the dual polyhedron.
    pub fn dual(self) -> PlatonicKind {
        match self {
            PlatonicKind::Tetrahedron => PlatonicKind::Tetrahedron,
            PlatonicKind::Cube => PlatonicKind::Octahedron,
            PlatonicKind::Octahedron => PlatonicKind::Cube,
            PlatonicKind::Dodecahedron => PlatonicKind::Icosahedron,
            PlatonicKind::Icosahedron => PlatonicKind::Dodecahedron,
        }
    }
}

/// The size of a Platonic solid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlatonicSize {
    /// Distance from the centre to every vertex.
    Circumradius(f64),
    /// Length of every edge.
    Edge(f64),
}

impl PlatonicSize {
    /// The JSON key of this way of giving the size (`circumradius` or `edge`).
    pub fn parameter(self) -> &'static str {
        match self {
            PlatonicSize::Circumradius(_) => "circumradius",
            PlatonicSize::Edge(_) => "edge",
        }
    }

    /// The number given.
    pub fn value(self) -> f64 {
        match self {
            PlatonicSize::Circumradius(x) | PlatonicSize::Edge(x) => x,
        }
    }

    /// The circumradius of a solid of kind `kind` with this size.
    pub fn circumradius(self, kind: PlatonicKind) -> f64 {
        match self {
            PlatonicSize::Circumradius(r) => r,
            PlatonicSize::Edge(a) => a / unit(kind).edge,
        }
    }

    /// Checks that the size is a finite positive number.
    pub fn check(self) -> Result<(), PolyhedronError> {
        let x = self.value();
        if x.is_finite() && x > 0.0 {
            Ok(())
        } else {
            Err(PolyhedronError::InvalidSize {
                parameter: self.parameter(),
            })
        }
    }
}

/// A Platonic solid at circumradius 1 and the data derived from it.
#[derive(Debug)]
pub(crate) struct UnitPlatonic {
    /// The solid (circumradius 1).
    pub polyhedron: Polyhedron,
    /// Outward unit normal of each face (in face order).
    pub normals: Vec<DVec3>,
    /// Distance from the centre to every face plane.
    pub inradius: f64,
    /// Edge length.
    pub edge: f64,
    /// Half extents of the bounding box.
    pub half_extents: DVec3,
}

/// The unit (circumradius 1) solid of a kind, built on first use.
pub(crate) fn unit(kind: PlatonicKind) -> &'static UnitPlatonic {
    static UNITS: OnceLock<Vec<UnitPlatonic>> = OnceLock::new();
    let units = UNITS.get_or_init(|| PlatonicKind::ALL.map(build_unit).into());
    &units[kind as usize]
}

fn build_unit(kind: PlatonicKind) -> UnitPlatonic {
    let raw = raw_vertices(kind);
    let r = raw[0].length();
    let vertices: Vec<DVec3> = raw.iter().map(|v| *v / r).collect();
    let faces = convex_faces(&vertices);
    let normals: Vec<DVec3> = faces
        .iter()
        .map(|f| {
            let [a, b, c] = [f[0], f[1], f[2]].map(|i| vertices[i as usize]);
            (b - a).cross(c - a).normalize()
        })
        .collect();
    let inradius = normals[0].dot(vertices[faces[0][0] as usize]);
    let edge = vertices[faces[0][0] as usize].distance(vertices[faces[0][1] as usize]);
    let half_extents = vertices.iter().fold(DVec3::ZERO, |m, v| m.max(v.abs()));
    let polyhedron = Polyhedron::new(vertices, faces).expect("Platonic faces are valid");
    UnitPlatonic {
        polyhedron,
        normals,
        inradius,
        edge,
        half_extents,
    }
}

/// The classic coordinates (all at the same distance from the origin).
fn raw_vertices(kind: PlatonicKind) -> Vec<DVec3> {
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    let signs = |n: usize| -> Vec<Vec<f64>> {
        (0..1usize << n)
            .map(|m| {
                (0..n)
                    .map(|b| if m >> b & 1 == 0 { 1.0 } else { -1.0 })
                    .collect()
            })
            .collect()
    };
    let cyclic = |a: f64, b: f64| -> Vec<DVec3> {
        signs(2)
            .iter()
            .flat_map(|s| {
                let (x, y) = (s[0] * a, s[1] * b);
                [
                    DVec3::new(0.0, x, y),
                    DVec3::new(x, y, 0.0),
                    DVec3::new(y, 0.0, x),
                ]
            })
            .collect()
    };
    let cube: Vec<DVec3> = signs(3)
        .iter()
        .map(|s| DVec3::new(s[0], s[1], s[2]))
        .collect();
    match kind {
        PlatonicKind::Tetrahedron => cube.into_iter().filter(|v| v.x * v.y * v.z > 0.0).collect(),
        PlatonicKind::Cube => cube,
        PlatonicKind::Octahedron => [DVec3::X, DVec3::Y, DVec3::Z]
            .into_iter()
            .flat_map(|a| [a, -a])
            .collect(),
        PlatonicKind::Icosahedron => cyclic(1.0, phi),
        PlatonicKind::Dodecahedron => {
            let mut v = cube;
            v.extend(cyclic(1.0 / phi, phi));
            v
        }
    }
}

impl Polyhedron {
    /// The Platonic solid `kind` of the given size, centred at the origin.
    pub fn platonic(kind: PlatonicKind, size: PlatonicSize) -> Result<Polyhedron, PolyhedronError> {
        size.check()?;
        Ok(unit(kind).polyhedron.scaled(size.circumradius(kind)))
    }
}
