//! PLY output with extra per-vertex scalar properties (e.g. curvatures): binary little endian,
//! `double x y z`, then one `double` per named property, and the faces as `uchar`-counted `uint`
//! lists. Viewers such as MeshLab and ParaView read the extra properties as vertex attributes;
//! [`read_mesh`](super::read_mesh) reads the geometry and skips them.

use super::{MeshIoError, write_atomic};
use crate::IndexedMesh;
use std::io::Write;
use std::path::Path;

/// Writes `mesh` with the per-vertex `properties` (name, one value per vertex) to `path`,
/// atomically. Names must be PLY identifiers (letters, digits, `_`); a property with the wrong
/// number of values, a bad name or a mesh index out of range is refused before anything is
/// written.
pub fn write_ply_with_scalars(
    path: &Path,
    mesh: &IndexedMesh,
    properties: &[(&str, &[f64])],
) -> Result<(), MeshIoError> {
    let invalid = |message: String| MeshIoError::InvalidMesh {
        path: path.to_path_buf(),
        message,
    };
    let n = mesh.positions.len();
    for (name, values) in properties {
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return Err(invalid(format!("bad property name \"{name}\"")));
        }
        if values.len() != n {
            return Err(invalid(format!(
                "property {name} has {} values for {n} vertices",
                values.len()
            )));
        }
    }
    if !mesh.indices_in_range() {
        return Err(invalid("a triangle refers to a missing vertex".into()));
    }
    write_atomic(path, |out: &mut dyn Write| {
        let mut header = format!(
            "ply\nformat binary_little_endian 1.0\ncomment written by solidkit\nelement vertex {n}\n\
             property double x\nproperty double y\nproperty double z\n"
        );
        for (name, _) in properties {
            header += &format!("property double {name}\n");
        }
        header += &format!(
            "element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
            mesh.triangles.len()
        );
        out.write_all(header.as_bytes())?;
        let mut row = Vec::with_capacity(8 * (3 + properties.len()));
        for (i, p) in mesh.positions.iter().enumerate() {
            row.clear();
            for x in p.to_array() {
                row.extend_from_slice(&x.to_le_bytes());
            }
            for (_, values) in properties {
                row.extend_from_slice(&values[i].to_le_bytes());
            }
            out.write_all(&row)?;
        }
        for t in &mesh.triangles {
            let mut face = [0u8; 13];
            face[0] = 3;
            for (k, i) in t.iter().enumerate() {
                face[1 + 4 * k..5 + 4 * k].copy_from_slice(&i.to_le_bytes());
            }
            out.write_all(&face)?;
        }
        Ok(())
    })
}
