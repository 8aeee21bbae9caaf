//! How the search stores a triangle's corners: as `f64` in general, as `f32` when every
//! position of the mesh is exactly an `f32` (any STL, any marching-cubes mesh). Widening an
//! `f32` to `f64` is exact, so both give the narrow phase the same corners, bit for bit, and the
//! `f32` form halves the largest array of the search (56 bytes a triangle instead of 96).

use glam::DVec3;

use super::predicates::Projection;
use super::triangles::Tri;

/// A triangle's three corners in some storage.
pub(crate) trait Corners: Copy + Send + Sync {
    /// Stores `p`; only called on corners [`Self::holds`] accepts.
    fn store(p: [DVec3; 3]) -> Self;
    /// The corners as stored.
    fn load(&self) -> [DVec3; 3];
    /// True when every position can be stored without change.
    fn holds(positions: &[DVec3]) -> bool;
}

impl Corners for [DVec3; 3] {
    fn store(p: [DVec3; 3]) -> Self {
        p
    }

    #[inline]
    fn load(&self) -> [DVec3; 3] {
        *self
    }

    fn holds(_: &[DVec3]) -> bool {
        true
    }
}

impl Corners for [[f32; 3]; 3] {
    fn store(p: [DVec3; 3]) -> Self {
        p.map(|c| c.to_array().map(|x| x as f32))
    }

    #[inline]
    fn load(&self) -> [DVec3; 3] {
        self.map(|c| DVec3::from_array(c.map(f64::from)))
    }

    fn holds(positions: &[DVec3]) -> bool {
        use rayon::prelude::*;
        positions
            .par_iter()
            .all(|p| p.to_array().iter().all(|&x| f64::from(x as f32) == x))
    }
}

/// A triangle taking part in the search.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Item<C> {
    /// Index into the mesh's triangles.
    pub(crate) id: u32,
    /// Its vertex indices.
    pub(crate) vertices: [u32; 3],
    /// Its corners.
    pub(crate) corners: C,
    /// A projection that keeps its area.
    pub(crate) proj: Projection,
}

impl<C: Corners> Item<C> {
    /// The triangle for the exact tests.
    #[inline]
    pub(crate) fn tri(&self) -> Tri {
        Tri {
            p: self.corners.load(),
            proj: self.proj,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_corners_hold_only_exact_positions_and_load_them_unchanged() {
        let exact = [
            DVec3::new(0.1f32 as f64, -0.0, 3.0e38f32 as f64),
            DVec3::new(-1.5, 1.0e-40f32 as f64, 7.0),
            DVec3::new(2.0, 0.25, -(0.3f32 as f64)),
        ];
        assert!(<[[f32; 3]; 3]>::holds(&exact));
        let stored = <[[f32; 3]; 3]>::store(exact);
        let back = stored.load();
        for k in 0..3 {
            assert_eq!(
                back[k].to_array().map(f64::to_bits),
                exact[k].to_array().map(f64::to_bits)
            );
        }
        assert!(!<[[f32; 3]; 3]>::holds(&[DVec3::new(0.1, 0.0, 0.0)]));
        assert!(!<[[f32; 3]; 3]>::holds(&[DVec3::new(1.0e39, 0.0, 0.0)]));
        assert!(<[DVec3; 3]>::holds(&[DVec3::new(0.1, 0.0, 0.0)]));
    }
}
