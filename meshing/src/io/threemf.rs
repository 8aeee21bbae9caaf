//! 3MF output (3D Manufacturing Format, core specification 1.3): a zip package (see
//! [`zip`](super::zip): stored entries, fixed timestamps) holding `[Content_Types].xml`,
//! `_rels/.rels` and the model part `3D/3dmodel.model`.
//!
//! Choices: the whole mesh is **one object** (`id="1"`, `type="model"`) with every shell in it (3MF
//! allows several shells in one mesh; the build has one item), `unit="millimeter"` (one solidkit
//! unit is written as one millimetre; solidkit itself is unitless), and coordinates written as the
//! shortest decimal that reads back to the same `f64`, so the model is exact. Vertex and triangle
//! order are those of the [`IndexedMesh`].

use std::io::{self, Write};

use super::zip::{ZipEntry, write_stored};
use crate::IndexedMesh;
use crate::colors::{DEFAULT_COLOR, FaceColors};

/// Path of the model part inside the package.
pub const MODEL_PATH: &str = "3D/3dmodel.model";

const CONTENT_TYPES: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
 <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
 <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>
"#;

const RELATIONSHIPS: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>
"#;

/// The `<basematerials>` group's id (the object stays `id="1"`).
const MATERIALS_ID: u32 = 2;

/// The model part's XML; with `colors`, a `<basematerials>` group (one `<base>` per colour, plus
/// the default colour when some triangle has none) referenced by the object (one colour) or by
/// each triangle (`pid`, `p1`).
fn model_xml(mesh: &IndexedMesh, colors: Option<&FaceColors>) -> io::Result<Vec<u8>> {
    let mut x = Vec::with_capacity(64 * mesh.positions.len() + 48 * mesh.triangles.len() + 512);
    x.write_all(
        br#"<?xml version="1.0" encoding="UTF-8"?>
<model unit="millimeter" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">
 <metadata name="Application">solidkit</metadata>
 <resources>
"#,
    )?;
    // Per triangle: the base index, when the object needs per-triangle properties.
    let mut per_triangle: Option<Vec<u32>> = None;
    match colors {
        Some(c) if !mesh.triangles.is_empty() => {
            let mut bases = c.palette.clone();
            let default = bases.len() as u32;
            if c.has_uncolored() {
                bases.push(DEFAULT_COLOR);
            }
            writeln!(x, "  <basematerials id=\"{MATERIALS_ID}\">")?;
            for (k, [r, g, b, a]) in bases.iter().enumerate() {
                writeln!(
                    x,
                    "   <base name=\"color {k}\" displaycolor=\"#{r:02X}{g:02X}{b:02X}{a:02X}\"/>"
                )?;
            }
            x.write_all(b"  </basematerials>\n")?;
            let index: Vec<u32> = (0..mesh.triangles.len())
                .map(|t| match c.faces.get(t) {
                    Some(&i) if i != FaceColors::NONE => i,
                    _ => default,
                })
                .collect();
            let first = index[0];
            writeln!(
                x,
                "  <object id=\"1\" type=\"model\" pid=\"{MATERIALS_ID}\" pindex=\"{first}\">"
            )?;
            if index.iter().any(|&i| i != first) {
                per_triangle = Some(index);
            }
        }
        _ => x.write_all(b"  <object id=\"1\" type=\"model\">\n")?,
    }
    x.write_all(b"   <mesh>\n    <vertices>\n")?;
    for p in &mesh.positions {
        writeln!(
            x,
            "     <vertex x=\"{}\" y=\"{}\" z=\"{}\"/>",
            p.x, p.y, p.z
        )?;
    }
    x.write_all(b"    </vertices>\n    <triangles>\n")?;
    for (t, [a, b, c]) in mesh.triangles.iter().enumerate() {
        match &per_triangle {
            Some(index) => writeln!(
                x,
                "     <triangle v1=\"{a}\" v2=\"{b}\" v3=\"{c}\" pid=\"{MATERIALS_ID}\" p1=\"{}\"/>",
                index[t]
            )?,
            None => writeln!(x, "     <triangle v1=\"{a}\" v2=\"{b}\" v3=\"{c}\"/>")?,
        }
    }
    x.write_all(
        br#"    </triangles>
   </mesh>
  </object>
 </resources>
 <build>
  <item objectid="1"/>
 </build>
</model>
"#,
    )?;
    Ok(x)
}

/// Writes `mesh` as a 3MF package, with per-triangle colours when `colors` is given.
pub(super) fn write(
    out: &mut dyn Write,
    mesh: &IndexedMesh,
    colors: Option<&FaceColors>,
) -> io::Result<()> {
    let model = model_xml(mesh, colors)?;
    write_stored(
        out,
        &[
            ZipEntry {
                name: "[Content_Types].xml",
                data: CONTENT_TYPES.as_bytes(),
            },
            ZipEntry {
                name: "_rels/.rels",
                data: RELATIONSHIPS.as_bytes(),
            },
            ZipEntry {
                name: MODEL_PATH,
                data: &model,
            },
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn coordinates_are_plain_decimals_that_read_back_exactly() {
        let p = DVec3::new(0.1, -1e-7, 123_456_789.125);
        let mesh = IndexedMesh::new(vec![p, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
        let xml = String::from_utf8(model_xml(&mesh, None).unwrap()).unwrap();
        let tag = xml.lines().find(|l| l.contains("<vertex")).unwrap();
        assert_eq!(
            tag.trim(),
            r#"<vertex x="0.1" y="-0.0000001" z="123456789.125"/>"#
        );
        let back: Vec<f64> = tag
            .split('"')
            .skip(1)
            .step_by(2)
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(back, p.to_array());
        assert!(xml.contains(r#"<triangle v1="0" v2="1" v3="2"/>"#));
        assert!(xml.contains(r#"unit="millimeter""#) && xml.contains(r#"<item objectid="1"/>"#));
    }
}
