//! glTF 2.0 binary output (`.glb`) for viewers: a 12-byte header, a JSON chunk and a BIN chunk
//! holding the positions (`FLOAT` VEC3, with the `min`/`max` the format requires) followed by the
//! triangle indices (`UNSIGNED_INT`), one mesh with one triangle primitive.
//!
//! The accessor data are the mesh's own coordinates rounded to `f32` (glTF has no doubles). glTF
//! is +Y up and solidkit is usually +Z up, so the one node carries the rotation −90° about x,
//! `(x, y, z) ↦ (x, z, −y)`: viewers show the solid upright, and tools that read the raw
//! accessors get the original coordinates. Units are whatever the mesh's are (glTF says metres).
//! The JSON is written in a fixed key order with shortest round-trip numbers, so the same mesh
//! always gives the same bytes.

use std::io::{self, Write};

use crate::IndexedMesh;
use crate::colors::FaceColors;

/// `glTF` in little-endian.
const MAGIC: u32 = 0x4654_6C67;
/// Chunk type `JSON`.
const CHUNK_JSON: u32 = 0x4E4F_534A;
/// Chunk type `BIN\0`.
const CHUNK_BIN: u32 = 0x004E_4942;
/// Quaternion (x, y, z, w) of −90° about the x axis: +Z up becomes +Y up.
const Z_UP_TO_Y_UP: &str = "[-0.7071067811865476,0,0,0.7071067811865476]";

/// Why `mesh` cannot be written as GLB, if it cannot.
pub(super) fn check_writable(mesh: &IndexedMesh) -> Result<(), String> {
    let bytes = 12 * mesh.positions.len() as u128 + 12 * mesh.triangles.len() as u128;
    if bytes > u32::MAX as u128 - 4096 {
        return Err("the mesh is too large for one GLB buffer (4 GiB)".into());
    }
    match mesh.positions.iter().position(|p| !p.as_vec3().is_finite()) {
        Some(v) => Err(format!(
            "vertex {v} ({}) does not fit in glTF's 32-bit floats",
            mesh.positions[v]
        )),
        None => Ok(()),
    }
}

/// The triangles of one primitive: its colour (`None`: no material) and triangle indices.
struct Group {
    color: Option<[u8; 4]>,
    triangles: Vec<usize>,
}

/// The primitives: one per colour in palette order, then the uncoloured triangles; without
/// colours, one primitive with every triangle in order.
fn groups(mesh: &IndexedMesh, colors: Option<&FaceColors>) -> Vec<Group> {
    let Some(c) = colors else {
        return vec![Group {
            color: None,
            triangles: (0..mesh.triangles.len()).collect(),
        }];
    };
    let mut groups: Vec<Group> = c
        .palette
        .iter()
        .map(|&p| Group {
            color: Some(p),
            triangles: Vec::new(),
        })
        .chain([Group {
            color: None,
            triangles: Vec::new(),
        }])
        .collect();
    let none = groups.len() - 1;
    for t in 0..mesh.triangles.len() {
        let g = match c.faces.get(t) {
            Some(&i) if (i as usize) < none => i as usize,
            _ => none,
        };
        groups[g].triangles.push(t);
    }
    groups.retain(|g| !g.triangles.is_empty());
    groups
}

/// glTF's `baseColorFactor` is linear: the sRGB channel `c` (0..1) in linear light.
fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The JSON chunk's text.
fn json(mesh: &IndexedMesh, groups: &[Group], positions_len: usize) -> String {
    let asset = r#""asset":{"version":"2.0","generator":"solidkit"}"#;
    if mesh.triangles.is_empty() {
        return format!(r#"{{{asset},"scene":0,"scenes":[{{"nodes":[]}}]}}"#);
    }
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for p in &mesh.positions {
        for (a, c) in p.as_vec3().to_array().into_iter().enumerate() {
            lo[a] = lo[a].min(c);
            hi[a] = hi[a].max(c);
        }
    }
    let triple = |v: [f32; 3]| format!("[{},{},{}]", v[0], v[1], v[2]);
    let indices_len: usize = groups.iter().map(|g| 12 * g.triangles.len()).sum();
    let (mut primitives, mut views, mut accessors, mut materials) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    views.push(format!(
        "{{\"buffer\":0,\"byteOffset\":0,\"byteLength\":{positions_len},\"target\":34962}}"
    ));
    accessors.push(format!(
        "{{\"bufferView\":0,\"componentType\":5126,\"count\":{},\"type\":\"VEC3\",\"min\":{},\"max\":{}}}",
        mesh.positions.len(),
        triple(lo),
        triple(hi)
    ));
    let mut offset = positions_len;
    for g in groups {
        let k = accessors.len();
        let len = 12 * g.triangles.len();
        views.push(format!(
            "{{\"buffer\":0,\"byteOffset\":{offset},\"byteLength\":{len},\"target\":34963}}"
        ));
        accessors.push(format!(
            "{{\"bufferView\":{k},\"componentType\":5125,\"count\":{},\"type\":\"SCALAR\"}}",
            3 * g.triangles.len()
        ));
        offset += len;
        let material = match g.color {
            None => String::new(),
            Some(c) => {
                let [r, gr, b] = [c[0], c[1], c[2]].map(|x| srgb_to_linear(f64::from(x) / 255.0));
                let a = f64::from(c[3]) / 255.0;
                let mode = if c[3] < 255 { "BLEND" } else { "OPAQUE" };
                materials.push(format!(
                    "{{\"pbrMetallicRoughness\":{{\"baseColorFactor\":[{r},{gr},{b},{a}],\"metallicFactor\":0,\"roughnessFactor\":1}},\"alphaMode\":\"{mode}\"}}"
                ));
                format!(",\"material\":{}", materials.len() - 1)
            }
        };
        primitives.push(format!(
            "{{\"attributes\":{{\"POSITION\":0}},\"indices\":{k}{material},\"mode\":4}}"
        ));
    }
    let materials = if materials.is_empty() {
        String::new()
    } else {
        format!(",\"materials\":[{}]", materials.join(","))
    };
    format!(
        concat!(
            "{{{asset},\"scene\":0,\"scenes\":[{{\"nodes\":[0]}}],",
            "\"nodes\":[{{\"mesh\":0,\"rotation\":{rotation}}}],",
            "\"meshes\":[{{\"primitives\":[{primitives}]}}]{materials},",
            "\"buffers\":[{{\"byteLength\":{total}}}],",
            "\"bufferViews\":[{views}],",
            "\"accessors\":[{accessors}]}}"
        ),
        asset = asset,
        rotation = Z_UP_TO_Y_UP,
        primitives = primitives.join(","),
        materials = materials,
        total = positions_len + indices_len,
        views = views.join(","),
        accessors = accessors.join(","),
    )
}

/// Writes `mesh` as GLB (the mesh must pass [`check_writable`]); with `colors`, one primitive
/// per colour with a material whose `baseColorFactor` is the colour (alpha below 1: `BLEND`).
pub(super) fn write(
    out: &mut dyn Write,
    mesh: &IndexedMesh,
    colors: Option<&FaceColors>,
) -> io::Result<()> {
    let empty = mesh.triangles.is_empty();
    let groups = groups(mesh, colors);
    let positions_len = if empty { 0 } else { 12 * mesh.positions.len() };
    let indices_len = if empty { 0 } else { 12 * mesh.triangles.len() };
    let mut text = json(mesh, &groups, positions_len).into_bytes();
    text.resize(text.len().next_multiple_of(4), b' ');
    let bin_len = positions_len + indices_len; // multiples of 4 already
    let too_big = || io::Error::new(io::ErrorKind::InvalidInput, "GLB over 4 GiB");
    let chunk = |len: usize| u32::try_from(len).map_err(|_| too_big());
    let mut total = 12 + 8 + text.len();
    if !empty {
        total += 8 + bin_len;
    }
    out.write_all(&MAGIC.to_le_bytes())?;
    out.write_all(&2u32.to_le_bytes())?;
    out.write_all(&chunk(total)?.to_le_bytes())?;
    out.write_all(&chunk(text.len())?.to_le_bytes())?;
    out.write_all(&CHUNK_JSON.to_le_bytes())?;
    out.write_all(&text)?;
    if empty {
        return Ok(());
    }
    out.write_all(&chunk(bin_len)?.to_le_bytes())?;
    out.write_all(&CHUNK_BIN.to_le_bytes())?;
    for p in &mesh.positions {
        for c in p.as_vec3().to_array() {
            out.write_all(&c.to_le_bytes())?;
        }
    }
    for g in &groups {
        for &t in &g.triangles {
            for i in mesh.triangles[t] {
                out.write_all(&i.to_le_bytes())?;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn glb(mesh: &IndexedMesh) -> Vec<u8> {
        let mut out = Vec::new();
        write(&mut out, mesh, None).unwrap();
        out
    }

    #[test]
    fn header_and_chunks_are_aligned_and_sized() {
        let tri = IndexedMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
        let bytes = glb(&tri);
        let le32 = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap());
        assert_eq!(le32(0), MAGIC);
        assert_eq!(le32(8) as usize, bytes.len());
        let json_len = le32(12) as usize;
        assert_eq!(json_len % 4, 0);
        assert_eq!(
            le32(20 + json_len) as usize,
            3 * 12 + 12,
            "positions and indices"
        );
        assert_eq!(bytes.len(), 20 + json_len + 8 + 48);
        assert_eq!(glb(&tri), bytes, "same mesh, same bytes");
    }

    #[test]
    fn empty_mesh_has_no_buffer_and_huge_coordinates_are_refused() {
        let bytes = glb(&IndexedMesh::default());
        let text = std::str::from_utf8(&bytes[20..]).unwrap();
        assert!(text.trim_end().ends_with('}') && !text.contains("buffers"));
        let far = IndexedMesh::new(vec![DVec3::splat(1e39)], vec![]);
        assert!(check_writable(&far).unwrap_err().contains("32-bit"));
    }
}
