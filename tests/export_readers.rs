//! Small independent readers of the 3MF and GLB files solidkit writes, for round-trip tests:
//! a zip reader for stored entries (checking every CRC-32 with a bitwise implementation), a
//! scanner of the 3MF model's `<vertex>` and `<triangle>` elements, and a GLB parser checking the
//! header, chunks, accessors and their `min`/`max`.

use glam::DVec3;
use solidkit_meshing::IndexedMesh;

/// Bitwise CRC-32 (IEEE, reflected), independent of the writer's table.
fn crc32(bytes: &[u8]) -> u32 {
    let mut c = !0u32;
    for &b in bytes {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 != 0 {
                (c >> 1) ^ 0xEDB8_8320
            } else {
                c >> 1
            };
        }
    }
    !c
}

fn le16(b: &[u8], at: usize) -> usize {
    u16::from_le_bytes([b[at], b[at + 1]]) as usize
}

fn le32(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes"))
}

/// The entries of a zip archive of stored entries, as (name, data), in directory order.
pub fn unzip(bytes: &[u8]) -> Vec<(String, Vec<u8>)> {
    let end = bytes.len() - 22;
    assert_eq!(le32(bytes, end), 0x0605_4b50, "end of central directory");
    let count = le16(bytes, end + 10);
    let mut at = le32(bytes, end + 16) as usize;
    let mut out = Vec::new();
    for _ in 0..count {
        assert_eq!(le32(bytes, at), 0x0201_4b50, "central header");
        assert_eq!(le16(bytes, at + 10), 0, "stored");
        let crc = le32(bytes, at + 16);
        let size = le32(bytes, at + 20) as usize;
        assert_eq!(le32(bytes, at + 24) as usize, size);
        let name_len = le16(bytes, at + 28);
        let extra = le16(bytes, at + 30) + le16(bytes, at + 32);
        let local = le32(bytes, at + 42) as usize;
        let name = String::from_utf8(bytes[at + 46..at + 46 + name_len].to_vec()).expect("name");
        assert_eq!(le32(bytes, local), 0x0403_4b50, "local header");
        let data_at = local + 30 + le16(bytes, local + 26) + le16(bytes, local + 28);
        let data = bytes[data_at..data_at + size].to_vec();
        assert_eq!(crc32(&data), crc, "CRC of {name}");
        out.push((name, data));
        at += 46 + name_len + extra;
    }
    out
}

/// The value of attribute `key` in an XML start tag.
fn attribute<'a>(tag: &'a str, key: &str) -> &'a str {
    let start = tag.find(&format!(" {key}=\"")).expect("attribute") + key.len() + 3;
    let len = tag[start..].find('"').expect("closing quote");
    &tag[start..start + len]
}

/// The mesh of a 3MF package: every `<vertex>` and `<triangle>` of its model part.
pub fn read_3mf(bytes: &[u8]) -> IndexedMesh {
    let entries = unzip(bytes);
    let names: Vec<&str> = entries.iter().map(|e| e.0.as_str()).collect();
    assert!(names.contains(&"[Content_Types].xml") && names.contains(&"_rels/.rels"));
    let model = &entries
        .iter()
        .find(|e| e.0 == "3D/3dmodel.model")
        .expect("model part")
        .1;
    let text = std::str::from_utf8(model).expect("UTF-8");
    assert!(text.contains("unit=\"millimeter\""));
    let mut mesh = IndexedMesh::default();
    for tag in text.split('<') {
        if tag.starts_with("vertex ") {
            let c = ["x", "y", "z"].map(|k| attribute(tag, k).parse::<f64>().expect("number"));
            mesh.positions.push(DVec3::from_array(c));
        } else if tag.starts_with("triangle ") {
            let t = ["v1", "v2", "v3"].map(|k| attribute(tag, k).parse::<u32>().expect("index"));
            mesh.triangles.push(t);
        }
    }
    mesh
}

/// The mesh of a GLB file (positions widened from `f32`).
pub fn read_glb(bytes: &[u8]) -> IndexedMesh {
    assert_eq!(&bytes[0..4], b"glTF");
    assert_eq!(le32(bytes, 4), 2);
    assert_eq!(le32(bytes, 8) as usize, bytes.len());
    let json_len = le32(bytes, 12) as usize;
    assert_eq!(&bytes[16..20], b"JSON");
    assert_eq!(json_len % 4, 0);
    let json: serde_json::Value = serde_json::from_slice(&bytes[20..20 + json_len]).expect("JSON");
    assert_eq!(json["asset"]["version"], "2.0");
    let bin_at = 20 + json_len;
    if bin_at == bytes.len() {
        return IndexedMesh::default();
    }
    let bin_len = le32(bytes, bin_at) as usize;
    assert_eq!(&bytes[bin_at + 4..bin_at + 8], b"BIN\0");
    let bin = &bytes[bin_at + 8..bin_at + 8 + bin_len];
    let prim = &json["meshes"][0]["primitives"][0];
    let accessor = |i: &serde_json::Value| &json["accessors"][i.as_u64().expect("index") as usize];
    let view = |a: &serde_json::Value| {
        let v = &json["bufferViews"][a["bufferView"].as_u64().expect("view") as usize];
        let at = v["byteOffset"].as_u64().unwrap_or(0) as usize;
        &bin[at..at + v["byteLength"].as_u64().expect("length") as usize]
    };
    let pos = accessor(&prim["attributes"]["POSITION"]);
    assert_eq!(pos["componentType"], 5126);
    assert_eq!(pos["type"], "VEC3");
    let data = view(pos);
    let floats: Vec<f32> = data
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes(c.try_into().expect("4")))
        .collect();
    let positions: Vec<DVec3> = floats
        .chunks_exact(3)
        .map(|c| DVec3::new(c[0] as f64, c[1] as f64, c[2] as f64))
        .collect();
    assert_eq!(
        positions.len() as u64,
        pos["count"].as_u64().expect("count")
    );
    for a in 0..3 {
        let lo = floats
            .iter()
            .skip(a)
            .step_by(3)
            .fold(f32::INFINITY, |m, &v| m.min(v));
        let hi = floats
            .iter()
            .skip(a)
            .step_by(3)
            .fold(f32::NEG_INFINITY, |m, &v| m.max(v));
        assert_eq!(pos["min"][a].as_f64().expect("min") as f32, lo);
        assert_eq!(pos["max"][a].as_f64().expect("max") as f32, hi);
    }
    let idx = accessor(&prim["indices"]);
    assert_eq!(idx["componentType"], 5125);
    let indices: Vec<u32> = view(idx)
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes(c.try_into().expect("4")))
        .collect();
    assert_eq!(indices.len() as u64, idx["count"].as_u64().expect("count"));
    let triangles = indices
        .chunks_exact(3)
        .map(|t| [t[0], t[1], t[2]])
        .collect();
    IndexedMesh::new(positions, triangles)
}
