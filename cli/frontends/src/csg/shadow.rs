//! The shadow of `projection(cut = false)`: the union of the children's triangles projected onto
//! z = 0. The triangles are the children's own faces where the tree is made of polyhedra and
//! boxes under unions and transforms (OpenSCAD's faceted primitives: the shadow is then exact up
//! to the grid), else those of a marching-cubes mesh of the children
//! ([`SHADOW_MESH_RESOLUTION`] cells). The samples of a 2D grid that some triangle covers are
//! inside; each crossing lies where the union of the triangles along the grid edge ends.

use super::contour::{Grid2, contour, region};
use super::error::CsgError;
use super::flat::Flat;
use super::operand::mesh_of;
use super::parser::Stmt;
use super::projection_grid::{RESOLUTION, SIMPLIFY_CELLS};
use glam::{DVec2, DVec3};
use solidkit_kernel::primitive::{MeshSource, Primitive, Shape};
use solidkit_kernel::triangulate::triangulate_polygon;
use solidkit_kernel::{NodeKind, Solid};

/// Cells along the longest side of the grid on which children without known faces are meshed.
pub const SHADOW_MESH_RESOLUTION: usize = 160;

/// The triangles bounding `solid`, where the tree gives them exactly.
fn exact_triangles(solid: &Solid) -> Option<Vec<[DVec3; 3]>> {
    solid.fold(|s, c: &[Option<Vec<[DVec3; 3]>>]| match s.kind() {
        NodeKind::Primitive(Primitive::Cuboid(b)) => {
            let bb = b.bbox();
            let corner = |i: usize| {
                DVec3::new(
                    if i & 1 == 0 { bb.min.x } else { bb.max.x },
                    if i & 2 == 0 { bb.min.y } else { bb.max.y },
                    if i & 4 == 0 { bb.min.z } else { bb.max.z },
                )
            };
            let quads = [
                [0, 2, 3, 1],
                [4, 5, 7, 6],
                [0, 1, 5, 4],
                [2, 6, 7, 3],
                [0, 4, 6, 2],
                [1, 3, 7, 5],
            ];
            Some(
                quads
                    .iter()
                    .flat_map(|q| {
                        [
                            [corner(q[0]), corner(q[1]), corner(q[2])],
                            [corner(q[0]), corner(q[2]), corner(q[3])],
                        ]
                    })
                    .collect(),
            )
        }
        NodeKind::Primitive(Primitive::Mesh(m)) => {
            let MeshSource::Faces { vertices, faces } = m.source() else {
                return None;
            };
            let mut out = Vec::new();
            for f in faces {
                let p: Vec<DVec3> = f
                    .iter()
                    .map(|&k| vertices.get(k as usize).copied())
                    .collect::<Option<_>>()?;
                if p.len() == 3 {
                    out.push([p[0], p[1], p[2]]);
                } else if p.len() > 3 {
                    let t = triangulate_polygon(&p).ok()?;
                    out.extend(t.iter().map(|t| t.map(|k| p[k as usize])));
                }
            }
            Some(out)
        }
        NodeKind::Union => c.iter().try_fold(Vec::new(), |mut all, t| {
            all.extend_from_slice(t.as_ref()?);
            Some(all)
        }),
        NodeKind::Transform(t) => c.first()?.as_ref().map(|tris| {
            tris.iter()
                .map(|tri| tri.map(|p| t.forward.transform_point3(p)))
                .collect()
        }),
        NodeKind::Color(_) => c.first()?.clone(),
        _ => None,
    })
}

/// Triangles projected to the plane (counter-clockwise), bucketed by the cells of a grid.
struct Shadow {
    triangles: Vec<[DVec2; 3]>,
    grid: Grid2,
    /// Triangle indices per cell (`j * nx + i`), in one array with offsets.
    start: Vec<usize>,
    items: Vec<u32>,
}

/// `cross(b - a, p - a)`.
fn orient(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    (b - a).perp_dot(p - a)
}

impl Shadow {
    fn new(triangles: Vec<[DVec2; 3]>, grid: Grid2) -> Shadow {
        let cells = grid.nx * grid.ny;
        let range = |t: &[DVec2; 3]| {
            let lo = t[0].min(t[1]).min(t[2]);
            let hi = t[0].max(t[1]).max(t[2]);
            let c = |v: f64, n: usize| (v.floor().max(0.0) as usize).min(n - 1);
            let a = (lo - grid.origin) / grid.cell;
            let b = (hi - grid.origin) / grid.cell;
            (
                c(a.x - 1e-9, grid.nx),
                c(b.x + 1e-9, grid.nx),
                c(a.y - 1e-9, grid.ny),
                c(b.y + 1e-9, grid.ny),
            )
        };
        let mut count = vec![0usize; cells + 1];
        for t in &triangles {
            let (i0, i1, j0, j1) = range(t);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    count[j * grid.nx + i + 1] += 1;
                }
            }
        }
        for k in 0..cells {
            count[k + 1] += count[k];
        }
        let mut fill = count.clone();
        let mut items = vec![0u32; count[cells]];
        for (n, t) in triangles.iter().enumerate() {
            let (i0, i1, j0, j1) = range(t);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    let c = j * grid.nx + i;
                    items[fill[c]] = n as u32;
                    fill[c] += 1;
                }
            }
        }
        Shadow {
            triangles,
            grid,
            start: count,
            items,
        }
    }

    /// The triangles registered in the cells `i0..=i1 × j0..=j1` (clamped to the grid).
    fn near(&self, i: [isize; 2], j: [isize; 2]) -> impl Iterator<Item = &[DVec2; 3]> {
        let clamp = |v: isize, n: usize| v.clamp(0, n as isize - 1) as usize;
        let (i0, i1) = (clamp(i[0], self.grid.nx), clamp(i[1], self.grid.nx));
        let (j0, j1) = (clamp(j[0], self.grid.ny), clamp(j[1], self.grid.ny));
        (j0..=j1).flat_map(move |j| {
            (i0..=i1).flat_map(move |i| {
                let c = j * self.grid.nx + i;
                self.items[self.start[c]..self.start[c + 1]]
                    .iter()
                    .map(|&n| &self.triangles[n as usize])
            })
        })
    }

    /// The cell coordinates of `p` (rounded down).
    fn cell_of(&self, p: DVec2) -> [isize; 2] {
        let q = ((p - self.grid.origin) / self.grid.cell).floor();
        [q.x as isize, q.y as isize]
    }

    /// Whether a triangle covers `p` (closed).
    fn covers(&self, p: DVec2) -> bool {
        let [i, j] = self.cell_of(p + DVec2::splat(0.5 * self.grid.cell));
        let eps = 1e-12 * self.grid.cell * self.grid.cell;
        self.near([i - 1, i], [j - 1, j]).any(|t| {
            orient(t[0], t[1], p) >= -eps
                && orient(t[1], t[2], p) >= -eps
                && orient(t[2], t[0], p) >= -eps
        })
    }

    /// Where the union of the triangles along the segment from the covered `a` to the uncovered
    /// `b` (one grid edge) ends.
    fn crossing(&self, a: DVec2, b: DVec2) -> DVec2 {
        let d = b - a;
        let [i, j] = self.cell_of((a + b) / 2.0);
        let mut spans: Vec<(f64, f64)> = self
            .near([i - 1, i + 1], [j - 1, j + 1])
            .filter_map(|t| {
                let (mut lo, mut hi) = (0.0f64, 1.0f64);
                for k in 0..3 {
                    let (u, v) = (t[k], t[(k + 1) % 3]);
                    // orient(u, v, a + s·d) = g0 + s·g1 ≥ 0.
                    let g0 = orient(u, v, a);
                    let g1 = (v - u).perp_dot(d);
                    if g1 == 0.0 {
                        if g0 < 0.0 {
                            return None;
                        }
                    } else if g1 > 0.0 {
                        lo = lo.max(-g0 / g1);
                    } else {
                        hi = hi.min(-g0 / g1);
                    }
                }
                (lo <= hi).then_some((lo, hi))
            })
            .collect();
        spans.sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut end = 0.0f64;
        for (lo, hi) in spans {
            if lo > end + 1e-9 {
                break;
            }
            end = end.max(hi);
        }
        a + d * end.min(1.0)
    }
}

/// The shadow of `solid` on the plane z = 0 (the union of its projection), or `None` when
/// empty.
pub fn shadow(stmt: &Stmt, solid: &Solid) -> Result<Option<Flat>, CsgError> {
    solid.validate().map_err(|e| stmt.error(e.to_string()))?;
    let space = match exact_triangles(solid) {
        Some(t) => t,
        None => {
            let mesh = mesh_of(stmt, solid, SHADOW_MESH_RESOLUTION)?;
            mesh.triangles
                .iter()
                .map(|t| t.map(|k| mesh.positions[k as usize]))
                .collect()
        }
    };
    let mut triangles = Vec::with_capacity(space.len());
    let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
    for t in &space {
        let [a, b, c] = t.map(|p| p.truncate());
        let area = orient(a, b, c);
        if area == 0.0 {
            continue;
        }
        lo = lo.min(a).min(b).min(c);
        hi = hi.max(a).max(b).max(c);
        triangles.push(if area > 0.0 { [a, b, c] } else { [a, c, b] });
    }
    if triangles.is_empty() {
        return Ok(None);
    }
    let grid = Grid2::covering(lo, hi, RESOLUTION);
    let shadow = Shadow::new(triangles, grid);
    let mut inside = vec![false; grid.samples()];
    for j in 0..=grid.ny {
        for i in 0..=grid.nx {
            inside[grid.index(i, j)] = shadow.covers(grid.point(i, j));
        }
    }
    let loops = contour(&grid, &inside, SIMPLIFY_CELLS * grid.cell, |a, b| {
        shadow.crossing(a, b)
    });
    Ok(region(loops))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_and_polyhedra_give_their_faces_others_do_not() {
        let b = Solid::cuboid(DVec3::ONE).rotate(DVec3::X, 30.0);
        let t = exact_triangles(&Solid::union_all(vec![b.clone(), b.translate(DVec3::X)]));
        assert_eq!(t.map(|t| t.len()), Some(24));
        assert!(exact_triangles(&Solid::sphere(1.0)).is_none());
        let d = Solid::difference_all(b.clone(), vec![Solid::sphere(0.1)]);
        assert!(exact_triangles(&d).is_none());
    }
}
