//! Tests of 3MF and GLB input: round trips through the writers, packages and documents built by
//! hand (deflated entries, several objects, build and node transforms, components, strips,
//! 16-bit and interleaved data), and hostile files (every truncation, corrupt data, zip bombs,
//! cycles, out-of-range indices) ending in located errors.

use std::io::Write as _;

use glam::DVec3;

use super::*;
use crate::topology::test_meshes::{cube, octahedron, torus, two_cubes};

fn encode(mesh: &IndexedMesh, format: MeshFormat) -> Vec<u8> {
    let opts = WriteOptions {
        format: Some(format),
        ..WriteOptions::default()
    };
    encode_mesh(mesh, &opts, "m").unwrap()
}

#[test]
fn writer_output_reads_back_identically() {
    let shifted = IndexedMesh::new(
        cube()
            .positions
            .iter()
            .map(|p| *p * DVec3::new(0.1, -1e-7, 3.3) + DVec3::new(1e6, 0.3, -2.7))
            .collect(),
        cube().triangles,
    );
    for mesh in [cube(), two_cubes(), octahedron(), torus(12, 7), shifted] {
        for format in [MeshFormat::ThreeMf, MeshFormat::Glb] {
            let bytes = encode(&mesh, format);
            let read = read_mesh_bytes(&bytes, format, "m").unwrap();
            assert_eq!(
                read,
                stored_mesh(&bytes, &mesh, format, "m").unwrap(),
                "{format:?}"
            );
            if format == MeshFormat::ThreeMf {
                assert_eq!(read, mesh);
            }
        }
    }
    for format in [MeshFormat::ThreeMf, MeshFormat::Glb] {
        let empty = read_mesh_bytes(&encode(&IndexedMesh::default(), format), format, "m");
        assert_eq!(empty.unwrap(), IndexedMesh::default());
    }
}

/// A zip of `(name, data, deflate)` entries, with the sizes each header declares.
pub(super) fn zip(entries: &[(&str, &[u8], bool)]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut directory = Vec::new();
    for &(name, data, deflate) in entries {
        let packed = if deflate {
            let mut e = flate2::write::DeflateEncoder::new(Vec::new(), flate2::Compression::best());
            e.write_all(data).unwrap();
            e.finish().unwrap()
        } else {
            data.to_vec()
        };
        let method: u16 = if deflate { 8 } else { 0 };
        let fields = |sig: u32| {
            let mut h = sig.to_le_bytes().to_vec();
            if sig == 0x0201_4b50 {
                h.extend(20u16.to_le_bytes());
            }
            h.extend(20u16.to_le_bytes());
            h.extend(0u16.to_le_bytes());
            h.extend(method.to_le_bytes());
            h.extend([0, 0, 0x21, 0]);
            h.extend(crc32(data).to_le_bytes());
            h.extend((packed.len() as u32).to_le_bytes());
            h.extend((data.len() as u32).to_le_bytes());
            h.extend((name.len() as u16).to_le_bytes());
            h.extend(0u16.to_le_bytes());
            h
        };
        let mut central = fields(0x0201_4b50);
        central.extend([0u8; 10]);
        central.extend((out.len() as u32).to_le_bytes());
        central.extend(name.as_bytes());
        directory.extend(central);
        out.extend(fields(0x0403_4b50));
        out.extend(name.as_bytes());
        out.extend(packed);
    }
    let start = out.len() as u32;
    out.extend(&directory);
    out.extend(0x0605_4b50u32.to_le_bytes());
    out.extend([0u8; 4]);
    out.extend((entries.len() as u16).to_le_bytes());
    out.extend((entries.len() as u16).to_le_bytes());
    out.extend((directory.len() as u32).to_le_bytes());
    out.extend(start.to_le_bytes());
    out.extend(0u16.to_le_bytes());
    out
}

const TRIANGLE_OBJECT: &str = r#"<object id="5" type="model"><mesh><vertices>
<vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" y="1" z="0"/>
</vertices><triangles><triangle v1="0" v2="1" v3="2"/></triangles></mesh></object>"#;

fn model(resources: &str, build: &str) -> String {
    format!(
        "<?xml version=\"1.0\"?>\n<model unit=\"millimeter\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\"><resources>{resources}</resources>\n<build>{build}</build></model>"
    )
}

#[test]
fn deflated_parts_several_objects_transforms_and_components() {
    let xml = model(
        &format!(
            "{TRIANGLE_OBJECT}<object id=\"9\"><components><component objectid=\"5\" transform=\"1 0 0 0 1 0 0 0 1 0 0 10\"/></components></object>"
        ),
        "<item objectid=\"5\"/><item objectid=\"5\" transform=\"2 0 0 0 2 0 0 0 2 100 0 0\"/><item objectid=\"9\" transform=\"1 0 0 0 1 0 0 0 1 0 7 0\"/>",
    );
    let rels = r#"<Relationships><Relationship Target="/3D/Other.model" Id="r" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>"#;
    let bytes = zip(&[
        ("_rels/.rels", rels.as_bytes(), true),
        ("3D/other.MODEL", xml.as_bytes(), true),
    ]);
    let m = read_mesh_bytes(&bytes, MeshFormat::ThreeMf, "p.3mf").unwrap();
    assert_eq!(m.triangles, vec![[0, 1, 2], [3, 4, 5], [6, 7, 8]]);
    assert_eq!(m.positions[4], DVec3::new(102.0, 0.0, 0.0));
    assert_eq!(m.positions[8], DVec3::new(0.0, 8.0, 10.0));
}

#[test]
fn bad_3mf_packages_give_located_errors() {
    let read = |bytes: &[u8]| {
        read_mesh_bytes(bytes, MeshFormat::ThreeMf, "p.3mf")
            .unwrap_err()
            .to_string()
    };
    let bad_index =
        model(TRIANGLE_OBJECT, "<item objectid=\"5\"/>").replace("v3=\"2\"", "v3=\"3\"");
    let e = read(&zip(&[("3D/3dmodel.model", bad_index.as_bytes(), false)]));
    assert!(
        e.starts_with("p.3mf: entry 3D/3dmodel.model: line 4: v3 = 3 is out of range"),
        "{e}"
    );
    let missing = model(TRIANGLE_OBJECT, "\n<item objectid=\"6\"/>");
    let e = read(&zip(&[("3D/3dmodel.model", missing.as_bytes(), true)]));
    assert!(e.contains("line 6: object 6 is not defined"), "{e}");
    let cycle = model(
        "<object id=\"1\"><components><component objectid=\"1\"/></components></object>",
        "<item objectid=\"1\"/>",
    );
    let e = read(&zip(&[("3D/3dmodel.model", cycle.as_bytes(), false)]));
    assert!(e.contains("nested more than"), "{e}");
    let e = read(&zip(&[("3D/other.xml", b"<model/>", false)]));
    assert!(e.contains("no 3D model part 3D/3dmodel.model"), "{e}");
    assert!(read(b"PK\x03\x04 not really").contains("not a zip package"));
    // A CRC mismatch.
    let good = model(TRIANGLE_OBJECT, "<item objectid=\"5\"/>");
    let mut bytes = zip(&[("3D/3dmodel.model", good.as_bytes(), false)]);
    let at = bytes.windows(6).position(|w| w == b"<model").unwrap();
    bytes[at + 1] = b'M';
    assert!(read(&bytes).contains("CRC-32 mismatch"));
}

#[test]
fn zip_bombs_are_refused() {
    let big = vec![b' '; 1 << 20];
    let bytes = zip(&[("3D/3dmodel.model", &big, true)]);
    assert!(bytes.len() < 4096, "{}", bytes.len());
    let e = threemf_read::read_limited(&bytes, "bomb.3mf", 1 << 19)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("over the limit") && e.contains("zip bomb"),
        "{e}"
    );
    // The header lies: it declares 1000 bytes but the data inflate to a mebibyte.
    let mut lying = bytes.clone();
    let declared = (big.len() as u32).to_le_bytes();
    for at in (0..lying.len() - 4)
        .filter(|&i| lying[i..i + 4] == declared)
        .collect::<Vec<_>>()
    {
        lying[at..at + 4].copy_from_slice(&1000u32.to_le_bytes());
    }
    let e = read_mesh_bytes(&lying, MeshFormat::ThreeMf, "bomb.3mf")
        .unwrap_err()
        .to_string();
    assert!(e.contains("inflates to more bytes than the 1000"), "{e}");
}

/// A GLB of `json` and `bin`.
fn glb(json: &str, bin: &[u8]) -> Vec<u8> {
    let mut text = json.as_bytes().to_vec();
    text.resize(text.len().next_multiple_of(4), b' ');
    let mut bin = bin.to_vec();
    bin.resize(bin.len().next_multiple_of(4), 0);
    let mut out = b"glTF".to_vec();
    out.extend(2u32.to_le_bytes());
    out.extend(((28 + text.len() + bin.len()) as u32).to_le_bytes());
    out.extend((text.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(text);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(bin);
    out
}

/// Four positions, interleaved with a 4-byte pad (stride 16), then u16 strip indices 0 1 2 3.
fn strip_bin() -> Vec<u8> {
    let mut bin = Vec::new();
    for p in [[0f32, 0., 0.], [1., 0., 0.], [0., 1., 0.], [1., 1., 0.]] {
        p.iter().for_each(|c| bin.extend(c.to_le_bytes()));
        bin.extend([0u8; 4]);
    }
    [0u16, 1, 2, 3]
        .iter()
        .for_each(|i| bin.extend(i.to_le_bytes()));
    bin
}

fn strip_json(nodes: &str, extra: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":{nodes},
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1,"mode":5}},{{"attributes":{{"POSITION":0}},"mode":0}}]}}],
"buffers":[{{"byteLength":72}}],
"bufferViews":[{{"buffer":0,"byteLength":64,"byteStride":16}},{{"buffer":0,"byteOffset":64,"byteLength":8}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"}},{{"bufferView":1,"componentType":5123,"count":4,"type":"SCALAR"}}]{extra}}}"#
    )
}

#[test]
fn glb_strips_strides_and_node_transforms() {
    // Root: translate +10 along glTF x, child: scale 2 and draw. glTF y is solidkit z.
    let nodes = r#"[{"translation":[10,0,0],"children":[1]},{"mesh":0,"scale":[2,2,2]}]"#;
    let m = read_mesh_bytes(
        &glb(&strip_json(nodes, ""), &strip_bin()),
        MeshFormat::Glb,
        "s.glb",
    )
    .unwrap();
    assert_eq!(
        m.triangles,
        vec![[0, 1, 2], [2, 1, 3]],
        "strip winding alternates"
    );
    assert_eq!(m.positions[3], DVec3::new(12.0, 0.0, 2.0));
    let matrix = r#"[{"mesh":0,"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1]}]"#;
    let m = read_mesh_bytes(
        &glb(&strip_json(matrix, ""), &strip_bin()),
        MeshFormat::Glb,
        "s.glb",
    )
    .unwrap();
    assert_eq!(m.positions[0], DVec3::new(5.0, -7.0, 6.0));
}

#[test]
fn bad_glb_files_give_located_errors() {
    let read = |bytes: &[u8]| {
        read_mesh_bytes(bytes, MeshFormat::Glb, "b.glb")
            .unwrap_err()
            .to_string()
    };
    let one = r#"[{"mesh":0}]"#;
    let good = glb(&strip_json(one, ""), &strip_bin());
    assert!(read(&good[..good.len() - 4]).starts_with("b.glb: byte "));
    let cycle = r#"[{"mesh":0,"children":[1]},{"children":[0]}]"#;
    assert!(read(&glb(&strip_json(cycle, ""), &strip_bin())).contains("reached twice"));
    let mut bin = strip_bin();
    bin[64] = 9;
    let e = read(&glb(&strip_json(one, ""), &bin));
    assert!(
        e.contains("meshes[0].primitives[0]: index 9 out of range"),
        "{e}"
    );
    let e = read(&glb(&strip_json(one, ""), &bin[..40]));
    assert!(e.contains("runs past the BIN chunk"), "{e}");
    let e = read(&glb(
        &strip_json(one, "").replace(
            "\"count\":4,\"type\":\"VEC3\"",
            "\"count\":-4,\"type\":\"VEC3\"",
        ),
        &strip_bin(),
    ));
    assert!(
        e.starts_with("b.glb: byte ") && e.contains("JSON chunk: invalid value"),
        "{e}"
    );
    let uri =
        strip_json(one, "").replace("\"byteLength\":72", "\"byteLength\":72,\"uri\":\"x.bin\"");
    assert!(read(&glb(&uri, &strip_bin())).contains("external"));
    assert!(read(b"glTF\x01\0\0\0").contains("version 1"));
    assert!(read(b"PK").contains("not a GLB file"));
}

#[test]
fn truncations_and_flipped_bytes_never_panic() {
    let files = [
        (
            MeshFormat::ThreeMf,
            encode(&octahedron(), MeshFormat::ThreeMf),
        ),
        (MeshFormat::Glb, encode(&octahedron(), MeshFormat::Glb)),
        (
            MeshFormat::Glb,
            glb(&strip_json(r#"[{"mesh":0}]"#, ""), &strip_bin()),
        ),
    ];
    for (format, bytes) in &files {
        for len in 0..bytes.len() {
            let e = read_mesh_bytes(&bytes[..len], *format, "t").unwrap_err();
            assert!(e.to_string().starts_with("t: "), "{e}");
        }
        for at in 0..bytes.len() {
            let mut flipped = bytes.clone();
            flipped[at] ^= 0x5A;
            let _ = read_mesh_bytes(&flipped, *format, "t");
        }
    }
}

#[test]
fn trimesh_scenes_read_as_two_closed_shells() {
    let three_mf = include_bytes!("../../../fixtures/meshes/io/trimesh_scene.3mf");
    let glb_file = include_bytes!("../../../fixtures/meshes/io/trimesh_scene.glb");
    // trimesh 5.2.0 measured 36.34815370372854 (box 24 + icosphere).
    for (bytes, format, tolerance) in [
        (&three_mf[..], MeshFormat::ThreeMf, 1e-12),
        (&glb_file[..], MeshFormat::Glb, 1e-5),
    ] {
        let mesh = read_mesh_bytes(bytes, format, "trimesh").unwrap();
        let r = crate::TopologyReport::of(&mesh);
        assert!(r.is_valid_solid(), "{format:?}: {r:?}");
        assert_eq!((r.vertices, r.faces, r.shells), (50, 92, 2), "{format:?}");
        assert!(
            (r.volume - 36.34815370372854).abs() < tolerance,
            "{format:?} {}",
            r.volume
        );
        // The 3MF is +Z up as written; the GLB's +Y up comes back as +Z up.
        let want = match format {
            MeshFormat::ThreeMf => [[-1.0, -1.5, -2.0], [11.5, 1.5, 2.5]],
            _ => [[-1.0, -2.5, -1.5], [11.5, 2.0, 1.5]],
        };
        for (got, want) in r.bbox.iter().flatten().zip(want.iter().flatten()) {
            assert!((got - want).abs() < 1e-6, "{format:?} {:?}", r.bbox);
        }
    }
}

#[test]
fn expansion_bombs_are_refused_before_copying() {
    // Object k + 1 holds object k twice: 2^25 triangles from a few kilobytes.
    let mut resources = TRIANGLE_OBJECT.replace("id=\"5\"", "id=\"1\"");
    for k in 1..=25 {
        resources += &format!(
            "<object id=\"{}\"><components><component objectid=\"{k}\"/><component objectid=\"{k}\"/></components></object>",
            k + 1
        );
    }
    let xml = model(&resources, "<item objectid=\"26\"/>");
    let bytes = zip(&[("3D/3dmodel.model", xml.as_bytes(), true)]);
    let e = read_mesh_bytes(&bytes, MeshFormat::ThreeMf, "b.3mf")
        .unwrap_err()
        .to_string();
    assert!(e.contains(": line 4: the build places more than"), "{e}");
    // A GLB accessor declaring 2^27 positions is refused from its count.
    let json = strip_json(r#"[{"mesh":0}]"#, "").replace(
        "\"count\":4,\"type\":\"VEC3\"",
        "\"count\":134217728,\"type\":\"VEC3\"",
    );
    let e = read_mesh_bytes(&glb(&json, &strip_bin()), MeshFormat::Glb, "b.glb")
        .unwrap_err()
        .to_string();
    assert!(e.contains("expands to more than"), "{e}");
}

#[test]
fn deeply_nested_glb_extras_are_skipped_without_recursion() {
    let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    let json = strip_json(r#"[{"mesh":0}]"#, &format!(",\"extras\":{deep}"));
    let m = read_mesh_bytes(&glb(&json, &strip_bin()), MeshFormat::Glb, "d.glb").unwrap();
    assert_eq!(m.triangles.len(), 2);
    let json = strip_json(&format!("[{{\"mesh\":0,\"extras\":{deep}}}]"), "");
    let m = read_mesh_bytes(&glb(&json, &strip_bin()), MeshFormat::Glb, "d.glb").unwrap();
    assert_eq!(m.triangles.len(), 2);
}
