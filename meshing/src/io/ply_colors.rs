//! PLY with per-face colours: the face element gains `uchar red, green, blue, alpha` after
//! `vertex_indices` (the common convention; MeshLab and trimesh read it). Uncoloured triangles get
//! [`DEFAULT_COLOR`](crate::colors::DEFAULT_COLOR).

use std::io::{self, Write};

use super::Encoding;
use super::ply::index_type;
use crate::IndexedMesh;
use crate::colors::{DEFAULT_COLOR, FaceColors};

/// Writes `mesh` as PLY with one colour per triangle.
pub(super) fn write(
    out: &mut dyn Write,
    mesh: &IndexedMesh,
    colors: &FaceColors,
    encoding: Encoding,
) -> io::Result<()> {
    let binary = encoding == Encoding::Binary;
    let (format, scalar) = if binary {
        ("binary_little_endian", "double")
    } else {
        ("ascii", "float")
    };
    writeln!(out, "ply")?;
    writeln!(out, "format {format} 1.0")?;
    writeln!(out, "comment written by solidkit")?;
    writeln!(out, "element vertex {}", mesh.positions.len())?;
    for axis in ["x", "y", "z"] {
        writeln!(out, "property {scalar} {axis}")?;
    }
    writeln!(out, "element face {}", mesh.triangles.len())?;
    writeln!(
        out,
        "property list uchar {} vertex_indices",
        index_type(mesh.positions.len())
    )?;
    for channel in ["red", "green", "blue", "alpha"] {
        writeln!(out, "property uchar {channel}")?;
    }
    writeln!(out, "end_header")?;
    if binary {
        for p in &mesh.positions {
            for c in p.to_array() {
                out.write_all(&c.to_le_bytes())?;
            }
        }
        for (t, tri) in mesh.triangles.iter().enumerate() {
            out.write_all(&[3])?;
            for i in tri {
                out.write_all(&i.to_le_bytes())?;
            }
            out.write_all(&colors.color_or(t, DEFAULT_COLOR))?;
        }
    } else {
        for p in &mesh.positions {
            writeln!(out, "{} {} {}", p.x, p.y, p.z)?;
        }
        for (t, [a, b, c]) in mesh.triangles.iter().enumerate() {
            let [r, g, bl, al] = colors.color_or(t, DEFAULT_COLOR);
            writeln!(out, "3 {a} {b} {c} {r} {g} {bl} {al}")?;
        }
    }
    Ok(())
}
