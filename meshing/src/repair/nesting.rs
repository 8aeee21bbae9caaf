//! Outward orientation per shell. Shells (faces connected through shared vertices) that enclose
//! no volume are removed (fins, flat sheets closed by hole filling). Each remaining shell is
//! wound so that its signed volume is positive, or negative when it lies inside an odd number of
//! other shells (a cavity), tested at one vertex of the shell: by one ray against each
//! containing shell that is closed and oriented (`rays.rs`, `cycles.rs`: one parallel pass over
//! the faces for every pair), otherwise by the generalised winding number (summed directly, or
//! through the kernel's fast winding-number tree for large containers).

use super::split::UnionFind;
use super::{cycles, rays};
use crate::IndexedMesh;
use glam::DVec3;
use solidkit_kernel::primitive::MeshSolid;

/// Above this many shells the nesting test (quadratic in shells) is skipped: all turn outward.
pub const MAX_NESTING_SHELLS: usize = 2000;

/// Triangle visits above which a containing shell's winding numbers go through a tree.
const DIRECT_WORK: usize = 4_000_000;

struct Shell {
    faces: Vec<usize>,
    volume: f64,
    area: f64,
    lo: DVec3,
    hi: DVec3,
}

/// What [`orient_shells`] did.
pub(super) struct Oriented {
    /// Shells removed (flat).
    pub removed: usize,
    /// For each face of the result, the face it was before and whether it was reversed.
    pub from: Vec<(u32, bool)>,
}

/// Orients each shell outward (cavities inward) and removes flat shells.
pub(super) fn orient_shells(positions: &[DVec3], tris: &mut Vec<[u32; 3]>) -> Oriented {
    let mut uf = UnionFind((0..positions.len() as u32).collect());
    for t in tris.iter() {
        uf.union(t[0], t[1]);
        uf.union(t[1], t[2]);
    }
    // Union-find root → shell (`u32::MAX`: none yet).
    let mut index_of = vec![u32::MAX; positions.len()];
    let mut shells: Vec<Shell> = Vec::new();
    for (f, t) in tris.iter().enumerate() {
        let root = uf.find(t[0]) as usize;
        if index_of[root] == u32::MAX {
            index_of[root] = shells.len() as u32;
            shells.push(Shell {
                faces: Vec::new(),
                volume: 0.0,
                area: 0.0,
                lo: DVec3::INFINITY,
                hi: DVec3::NEG_INFINITY,
            });
        }
        shells[index_of[root] as usize].faces.push(f);
    }
    for s in &mut shells {
        let origin = positions[tris[s.faces[0]][0] as usize];
        for &f in &s.faces {
            let [a, b, c] = tris[f].map(|i| positions[i as usize]);
            let (a0, b0, c0) = (a - origin, b - origin, c - origin);
            s.volume += a0.dot(b0.cross(c0)) / 6.0;
            s.area += (b - a).cross(c - a).length() * 0.5;
            s.lo = s.lo.min(a).min(b).min(c);
            s.hi = s.hi.max(a).max(b).max(c);
        }
    }
    let flat = |s: &Shell| s.volume.abs() <= 1e-9 * s.area.powf(1.5) || s.area == 0.0;
    let removed = shells.iter().filter(|s| flat(s)).count();
    shells.retain(|s| !flat(s));
    let depth = nesting_depths(positions, tris, &shells);
    let flip: Vec<bool> = shells
        .iter()
        .zip(&depth)
        .map(|(s, &d)| (s.volume > 0.0) != (d % 2 == 0))
        .collect();
    let mut out = Vec::with_capacity(tris.len());
    let mut from = Vec::with_capacity(tris.len());
    for (s, &fl) in shells.iter().zip(&flip) {
        for &f in &s.faces {
            let t = tris[f];
            out.push(if fl { [t[0], t[2], t[1]] } else { t });
            from.push((f as u32, fl));
        }
    }
    *tris = out;
    Oriented { removed, from }
}

/// Per shell, how many other shells contain its first vertex (all 0 above
/// [`MAX_NESTING_SHELLS`] shells). Only shells whose bounding box contains the other's are
/// tested. A container that is a 2-cycle (closed and oriented, `cycles.rs`) is tested by one ray
/// per contained shell (`rays.rs`: one pass over the faces for all pairs); the others, and the
/// pairs a ray leaves ambiguous (a point on or next to the container), by the generalised
/// winding number, through the kernel's fast winding-number tree when the direct sums would cost
/// more than [`DIRECT_WORK`] triangle visits. Both give the same answer on a cycle.
fn nesting_depths(positions: &[DVec3], tris: &[[u32; 3]], shells: &[Shell]) -> Vec<u32> {
    let mut depth = vec![0u32; shells.len()];
    if shells.len() > MAX_NESTING_SHELLS {
        return depth;
    }
    let point = |s: &Shell| positions[tris[s.faces[0]][0] as usize];
    // Per shell, the other shells whose bounding box contains its own (ascending).
    let containers: Vec<Vec<u32>> = shells
        .iter()
        .enumerate()
        .map(|(i, s)| {
            (0..shells.len())
                .filter(|&j| {
                    let t = &shells[j];
                    i != j && t.lo.cmple(s.lo).all() && t.hi.cmpge(s.hi).all()
                })
                .map(|j| j as u32)
                .collect()
        })
        .collect();
    let mut used: Vec<u32> = containers.iter().flatten().copied().collect();
    if used.is_empty() {
        return depth;
    }
    used.sort_unstable();
    used.dedup();
    let mut cycle = vec![false; shells.len()];
    for &j in &used {
        cycle[j as usize] = cycles::is_cycle(tris, &shells[j as usize].faces);
    }
    let mut face_shell = vec![u32::MAX; tris.len()];
    for &j in used.iter().filter(|&&j| cycle[j as usize]) {
        for &f in &shells[j as usize].faces {
            face_shell[f] = j;
        }
    }
    let queries: Vec<DVec3> = shells.iter().map(point).collect();
    let by_ray: Vec<Vec<u32>> = containers
        .iter()
        .map(|c| c.iter().copied().filter(|&j| cycle[j as usize]).collect())
        .collect();
    let scale = shells
        .iter()
        .map(|s| (s.hi - s.lo).length() + s.lo.abs().max(s.hi.abs()).max_element())
        .fold(0.0, f64::max);
    let pairs = rays::Pairs {
        queries: &queries,
        containers: &by_ray,
        face_shell: &face_shell,
    };
    let ray_answers = rays::inside_by_rays(positions, tris, &pairs, scale);
    // Per container, the shells left to the winding number.
    let mut by_winding: Vec<Vec<usize>> = vec![Vec::new(); shells.len()];
    for (i, c) in containers.iter().enumerate() {
        for &j in c {
            let answer = by_ray[i]
                .binary_search(&j)
                .ok()
                .and_then(|k| ray_answers[i][k]);
            match answer {
                Some(inside) => depth[i] += u32::from(inside),
                None => by_winding[j as usize].push(i),
            }
        }
    }
    for (t, inside) in shells.iter().zip(by_winding) {
        if inside.is_empty() {
            continue;
        }
        let tree = (t.faces.len() * inside.len() > DIRECT_WORK)
            .then(|| {
                let mesh = IndexedMesh::new(
                    positions.to_vec(),
                    t.faces.iter().map(|&f| tris[f]).collect(),
                );
                MeshSolid::from_mesh(&mesh).ok()
            })
            .flatten();
        for i in inside {
            let p = point(&shells[i]);
            let w = match &tree {
                Some(solid) => solid.winding_number(p),
                None => winding(positions, tris, &t.faces, p),
            };
            if w.abs() > 0.5 {
                depth[i] += 1;
            }
        }
    }
    depth
}

/// The generalised winding number of `faces` at `p` (solid angles, Van Oosterom–Strackee).
pub(super) fn winding(positions: &[DVec3], tris: &[[u32; 3]], faces: &[usize], p: DVec3) -> f64 {
    let mut sum = 0.0;
    for &f in faces {
        let [a, b, c] = tris[f].map(|i| positions[i as usize] - p);
        let (la, lb, lc) = (a.length(), b.length(), c.length());
        let num = a.dot(b.cross(c));
        let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
        sum += 2.0 * num.atan2(den);
    }
    sum / (4.0 * std::f64::consts::PI)
}
