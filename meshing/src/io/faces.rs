//! Where the readers put the faces they read: triangulated (the [`IndexedMesh`] readers), or kept
//! as polygons (the [`PolygonMesh`] readers, for subdivision and other polygon tools).
//!
//! [`IndexedMesh`]: crate::IndexedMesh
//! [`PolygonMesh`]: super::PolygonMesh

use glam::DVec3;

use super::{PolygonError, triangulate_polygon};

/// Receives the faces of a file, corner indices already checked against the vertex count.
pub(super) trait FaceSink {
    /// Adds one face; on error nothing is added.
    fn add(&mut self, positions: &[DVec3], corners: &[u32]) -> Result<(), PolygonError>;
    /// Every corner stored so far, for renumbering vertices.
    fn corners_mut(&mut self) -> &mut [u32];
}

/// Triangles: polygons triangulated by [`triangulate_polygon`].
/// A reader of one polygon format: fills the sink with the faces, returns the positions.
pub(super) type ReadFaces =
    fn(&[u8], &str, &mut dyn FaceSink) -> Result<Vec<glam::DVec3>, super::MeshIoError>;

/// Reads a file of a polygon format as triangles (n-gons triangulated by the sink).
pub(super) fn triangles(
    bytes: &[u8],
    name: &str,
    read_faces: ReadFaces,
) -> Result<crate::IndexedMesh, super::MeshIoError> {
    let mut triangles = Vec::new();
    let positions = read_faces(bytes, name, &mut triangles)?;
    Ok(crate::IndexedMesh::new(positions, triangles))
}

impl FaceSink for Vec<[u32; 3]> {
    fn add(&mut self, positions: &[DVec3], corners: &[u32]) -> Result<(), PolygonError> {
        triangulate_polygon(positions, corners, self)
    }

    fn corners_mut(&mut self) -> &mut [u32] {
        self.as_flattened_mut()
    }
}

/// Polygons kept as they are, stored flat: face `f` is `corners[ends[f - 1]..ends[f]]`.
#[derive(Debug, Default)]
pub(super) struct Polygons {
    pub corners: Vec<u32>,
    pub ends: Vec<usize>,
}

impl Polygons {
    /// The faces as vertex loops.
    pub fn into_faces(self) -> Vec<Vec<u32>> {
        let mut start = 0;
        self.ends
            .iter()
            .map(|&end| {
                let face = self.corners[start..end].to_vec();
                start = end;
                face
            })
            .collect()
    }
}

impl FaceSink for Polygons {
    /// Checks what every polygon tool needs: at least three corners, in range, none repeated.
    fn add(&mut self, positions: &[DVec3], corners: &[u32]) -> Result<(), PolygonError> {
        if corners.len() < 3 {
            return Err(PolygonError::TooFewCorners(corners.len()));
        }
        if let Some(&index) = corners.iter().find(|&&i| i as usize >= positions.len()) {
            let count = positions.len();
            return Err(PolygonError::IndexOutOfRange { index, count });
        }
        if let Some((first, second)) = repeated(corners) {
            return Err(PolygonError::CoincidentCorners { first, second });
        }
        self.corners.extend_from_slice(corners);
        self.ends.push(self.corners.len());
        Ok(())
    }

    fn corners_mut(&mut self) -> &mut [u32] {
        &mut self.corners
    }
}

/// The first two positions (1-based along the face) holding the same vertex.
fn repeated(corners: &[u32]) -> Option<(usize, usize)> {
    if corners.len() <= 32 {
        return (0..corners.len()).find_map(|i| {
            (i + 1..corners.len())
                .find(|&j| corners[i] == corners[j])
                .map(|j| (i + 1, j + 1))
        });
    }
    let mut sorted: Vec<(u32, usize)> = corners.iter().copied().zip(1..).collect();
    sorted.sort_unstable();
    sorted
        .windows(2)
        .find(|w| w[0].0 == w[1].0)
        .map(|w| (w[0].1, w[1].1))
}
