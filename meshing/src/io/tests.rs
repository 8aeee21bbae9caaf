//! Tests of the I/O module as a whole: round trips through every format and encoding, located
//! errors, polygon faces, extra PLY data, and robustness against arbitrary bytes.

use std::path::Path;

use glam::DVec3;

use super::*;

const FACES_OBJ: &[u8] = include_bytes!("../../../fixtures/meshes/io/faces.obj");
const BAD_INDEX_OBJ: &[u8] = include_bytes!("../../../fixtures/meshes/io/bad_index.obj");
const EXTRA_PLY: &[u8] = include_bytes!("../../../fixtures/meshes/io/extra.ply");
const COMMENTED_OFF: &[u8] = include_bytes!("../../../fixtures/meshes/io/commented.off");

/// Every format and encoding combination.
const ALL: [(MeshFormat, Encoding); 6] = [
    (MeshFormat::Stl, Encoding::Binary),
    (MeshFormat::Stl, Encoding::Ascii),
    (MeshFormat::Obj, Encoding::Ascii),
    (MeshFormat::Ply, Encoding::Binary),
    (MeshFormat::Ply, Encoding::Ascii),
    (MeshFormat::Off, Encoding::Ascii),
];

/// Renumbers vertices in order of first use by the triangles (what STL welding and `tobj`
/// produce), dropping unused ones.
fn first_use_order(mesh: &IndexedMesh) -> IndexedMesh {
    let mut new_index = vec![u32::MAX; mesh.positions.len()];
    let mut positions = Vec::new();
    let triangles = mesh
        .triangles
        .iter()
        .map(|t| {
            t.map(|i| {
                let slot = &mut new_index[i as usize];
                if *slot == u32::MAX {
                    *slot = positions.len() as u32;
                    positions.push(mesh.positions[i as usize]);
                }
                *slot
            })
        })
        .collect();
    IndexedMesh::new(positions, triangles)
}

/// The unit cube: 8 vertices, 12 outward (counter-clockwise) triangles.
fn cube() -> IndexedMesh {
    let positions = (0..8)
        .map(|i| DVec3::new(f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)))
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let triangles = quads
        .iter()
        .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
        .collect();
    first_use_order(&IndexedMesh::new(positions, triangles))
}

/// An octahedron with half-integer coordinates: 6 vertices, 8 triangles.
fn octahedron() -> IndexedMesh {
    let p = |x, y, z| DVec3::new(x, y, z) * 1.5 + DVec3::splat(-0.25);
    let positions = vec![
        p(1.0, 0.0, 0.0),
        p(-1.0, 0.0, 0.0),
        p(0.0, 1.0, 0.0),
        p(0.0, -1.0, 0.0),
        p(0.0, 0.0, 1.0),
        p(0.0, 0.0, -1.0),
    ];
    let triangles = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    first_use_order(&IndexedMesh::new(positions, triangles))
}

fn encoded(mesh: &IndexedMesh, format: MeshFormat, encoding: Encoding) -> Vec<u8> {
    let mut bytes = Vec::new();
    encode(&mut bytes, mesh, format, encoding).expect("encode to memory");
    bytes
}

fn read(bytes: &[u8], format: MeshFormat) -> Result<IndexedMesh, MeshIoError> {
    read_mesh_bytes(bytes, format, &format!("t.{}", format.extension()))
}

fn err(bytes: &[u8], format: MeshFormat) -> MeshIoError {
    read(bytes, format).expect_err("the input is invalid")
}

/// Sum of triangle areas; asserts each triangle faces like `normal`.
fn area_facing(mesh: &IndexedMesh, triangles: &[[u32; 3]], normal: DVec3) -> f64 {
    triangles
        .iter()
        .map(|&[a, b, c]| {
            let [a, b, c] = [a, b, c].map(|i| mesh.positions[i as usize]);
            let n = (b - a).cross(c - a);
            assert!(n.dot(normal) > 0.0, "triangle wound against its face");
            n.length() / 2.0
        })
        .sum()
}

#[test]
fn round_trip_through_files_in_every_format_and_encoding() {
    let dir = tempfile::tempdir().expect("temp dir");
    for mesh in [cube(), octahedron()] {
        for (format, encoding) in ALL {
            let path = dir.path().join(format!("m.{}", format.extension()));
            let opts = WriteOptions {
                format: None,
                encoding,
            };
            write_mesh_with(&path, &mesh, &opts).expect("write");
            let back = read_mesh(&path).expect("read back");
            assert_eq!(back, mesh, "{format:?} {encoding:?}");
        }
    }
    let stl = read_mesh_bytes(
        &encoded(&cube(), MeshFormat::Stl, Encoding::Binary),
        MeshFormat::Stl,
        "c.stl",
    )
    .expect("stl");
    assert_eq!((stl.vertex_count(), stl.triangle_count()), (8, 12));
}

#[test]
fn write_mesh_defaults_to_binary_and_follows_the_extension_in_any_case() {
    let dir = tempfile::tempdir().expect("temp dir");
    let stl = dir.path().join("CUBE.STL");
    write_mesh(&stl, &cube()).expect("write");
    let bytes = std::fs::read(&stl).expect("read");
    assert_eq!(bytes.len(), 84 + 50 * 12);
    let ply = dir.path().join("cube.Ply");
    write_mesh(&ply, &cube()).expect("write");
    assert!(
        std::fs::read(&ply)
            .expect("read")
            .starts_with(b"ply\nformat binary_little_endian")
    );
    assert_eq!(read_mesh(&ply).expect("read ply"), cube());
    let forced = dir.path().join("forced.txt");
    let opts = WriteOptions {
        format: Some(MeshFormat::Off),
        encoding: Encoding::Binary,
    };
    write_mesh_with(&forced, &cube(), &opts).expect("explicit format");
    assert!(std::fs::read(&forced).expect("read").starts_with(b"OFF\n"));
}

#[test]
fn precise_coordinates_survive_ply_and_off_exactly() {
    let mut rng = Rng(7);
    let mut mesh = octahedron();
    for p in &mut mesh.positions {
        *p = DVec3::new(rng.float(), rng.float(), rng.float()) * 1e3;
    }
    for (format, encoding) in [
        (MeshFormat::Ply, Encoding::Binary),
        (MeshFormat::Ply, Encoding::Ascii),
        (MeshFormat::Off, Encoding::Ascii),
    ] {
        let back = read(&encoded(&mesh, format, encoding), format).expect("read");
        assert_eq!(back, mesh, "{format:?} {encoding:?}");
    }
}

#[test]
fn unknown_extensions_are_unsupported() {
    let dir = tempfile::tempdir().expect("temp dir");
    for name in ["mesh.xyz", "mesh", "mesh.stl.bak"] {
        let path = dir.path().join(name);
        let e = write_mesh(&path, &cube()).expect_err("unsupported");
        assert!(matches!(e, MeshIoError::UnsupportedFormat { .. }), "{e}");
        assert!(matches!(
            read_mesh(&path),
            Err(MeshIoError::UnsupportedFormat { .. })
        ));
    }
    assert!(!dir.path().join("mesh.xyz").exists());
    assert_eq!(
        MeshFormat::from_path(Path::new("a/b.oBj")).ok(),
        Some(MeshFormat::Obj)
    );
    assert_eq!(MeshFormat::from_extension("OFF"), Some(MeshFormat::Off));
}

#[test]
fn missing_file_is_an_io_error_naming_it() {
    let e = read_mesh(Path::new("/definitely/not/here.stl")).expect_err("missing");
    assert!(matches!(e, MeshIoError::File(_)));
    assert!(e.to_string().starts_with("/definitely/not/here.stl: "));
}

#[test]
fn invalid_meshes_are_not_written() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("bad.obj");
    let mut mesh = cube();
    mesh.triangles[3][1] = 99;
    let e = write_mesh(&path, &mesh).expect_err("index out of range");
    assert!(
        e.to_string().contains("triangle 3 refers to vertex 99"),
        "{e}"
    );
    let mut mesh = cube();
    mesh.positions[2].y = f64::NAN;
    assert!(write_mesh(&path, &mesh).is_err());
    let mut mesh = cube();
    mesh.positions[0].x = 1e300;
    let e = write_mesh(&dir.path().join("big.stl"), &mesh).expect_err("f32 overflow");
    assert!(e.to_string().contains("32-bit"), "{e}");
    write_mesh(&dir.path().join("big.ply"), &mesh).expect("PLY stores doubles");
    assert_eq!(std::fs::read_dir(dir.path()).expect("dir").count(), 1);
}

#[test]
fn truncated_binary_stl_reports_the_byte_offset() {
    let mut bytes = encoded(&cube(), MeshFormat::Stl, Encoding::Binary);
    bytes.truncate(184);
    let e = read_mesh_bytes(&bytes, MeshFormat::Stl, "broken.stl").expect_err("truncated");
    assert_eq!(
        e.to_string(),
        "broken.stl: byte 184: truncated binary STL: header says 12 triangles (684 bytes) \
         but the file has 184 bytes"
    );
    assert!(matches!(
        e,
        MeshIoError::Parse {
            location: Location::Byte(184),
            ..
        }
    ));
    let mut longer = encoded(&cube(), MeshFormat::Stl, Encoding::Binary);
    longer.extend_from_slice(&[0; 7]);
    assert_eq!(
        err(&longer, MeshFormat::Stl).location(),
        Some(Location::Byte(684))
    );
    assert!(
        err(b"tiny", MeshFormat::Stl)
            .to_string()
            .contains("not an STL file")
    );
}

#[test]
fn binary_stl_whose_header_starts_with_solid_is_binary() {
    let mut bytes = encoded(&cube(), MeshFormat::Stl, Encoding::Binary);
    bytes[..12].copy_from_slice(b"solid cube  ");
    assert_eq!(read(&bytes, MeshFormat::Stl).expect("binary"), cube());
}

#[test]
fn stl_rejects_non_finite_coordinates_where_they_are() {
    let mut bytes = encoded(&cube(), MeshFormat::Stl, Encoding::Binary);
    // Triangle 1, corner 2, y: 84 + 50 + 12 + 12 + 4.
    let at = 84 + 50 + 12 + 12 + 4;
    bytes[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
    let e = err(&bytes, MeshFormat::Stl);
    assert_eq!(e.location(), Some(Location::Byte(at as u64)), "{e}");
    let text = String::from_utf8(encoded(&cube(), MeshFormat::Stl, Encoding::Ascii)).expect("utf8");
    let bad = text.replacen("vertex 0e0 0e0 0e0", "vertex 0e0 NaN 0e0", 1);
    assert_ne!(bad, text);
    let e = err(bad.as_bytes(), MeshFormat::Stl);
    assert!(
        e.to_string()
            .starts_with("t.stl:4: coordinate 'NaN' is not a finite"),
        "{e}"
    );
    let huge = text.replacen("vertex 0e0 0e0 0e0", "vertex 0e0 1e39 0e0", 1);
    assert!(
        err(huge.as_bytes(), MeshFormat::Stl)
            .to_string()
            .contains("32-bit")
    );
}

#[test]
fn ascii_stl_errors_name_the_line() {
    let text = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n  \
                endloop\n endfacet\nendsolid x\n";
    let e = err(text.as_bytes(), MeshFormat::Stl);
    assert_eq!(e.to_string(), "t.stl:6: expected 'vertex', found 'endloop'");
    let cut = "solid x\n facet normal 0 0 1\n  outer loop\n";
    assert!(
        err(cut.as_bytes(), MeshFormat::Stl)
            .to_string()
            .contains("unexpected end of file")
    );
    let two = "solid a\nendsolid a\nsolid b\nfacet normal 0 0 0 outer loop vertex 0 0 0 vertex 1 0 \
               0 vertex 0 1 0 endloop endfacet\nendsolid b\n";
    assert_eq!(
        read(two.as_bytes(), MeshFormat::Stl)
            .expect("two solids")
            .triangle_count(),
        1
    );
}

#[test]
fn obj_index_out_of_range_names_the_line() {
    let e = read_mesh_bytes(BAD_INDEX_OBJ, MeshFormat::Obj, "bad.obj").expect_err("bad index");
    assert_eq!(
        e.to_string(),
        "bad.obj:7: face index 12 out of range (the file has 4 vertices)"
    );
}

#[test]
fn obj_polygons_are_triangulated_with_their_winding_and_area() {
    let mesh = read(FACES_OBJ, MeshFormat::Obj).expect("faces.obj");
    assert_eq!(mesh.vertex_count(), 19);
    // quad, pentagon, clockwise L-shaped hexagon, non-convex dart quad.
    let expected = [(4, 2.0), (5, 3.0), (6, 3.0), (4, 4.0)];
    let mut first_triangle = 0;
    let mut first_vertex = 0;
    for (corners, area) in expected {
        let face: Vec<DVec3> = mesh.positions[first_vertex..first_vertex + corners].to_vec();
        let normal = newell_normal(&face);
        let triangles = &mesh.triangles[first_triangle..first_triangle + corners - 2];
        let got = area_facing(&mesh, triangles, normal);
        assert!((got - area).abs() < 1e-12, "area {got} vs {area}");
        assert!((normal.length() / 2.0 - area).abs() < 1e-12);
        first_triangle += corners - 2;
        first_vertex += corners;
    }
    assert_eq!(mesh.triangle_count(), first_triangle);
    assert!(
        newell_normal(&mesh.positions[9..15]).z < 0.0,
        "the hexagon is clockwise"
    );
}

#[test]
fn obj_objects_sharing_vertices_are_joined() {
    let mesh = cube();
    let mut text = String::new();
    for p in &mesh.positions {
        text += &format!("v {} {} {}\n", p.x, p.y, p.z);
    }
    for (t, [a, b, c]) in mesh.triangles.iter().enumerate() {
        if t % 4 == 0 {
            text += &format!("g part{t}\nusemtl m{t}\n");
        }
        text += &format!("f {} {} {}\n", a + 1, b + 1, c + 1);
    }
    text += "mtllib missing.mtl\nl 1 2 3\nl 4 5\np 1\n";
    assert_eq!(
        read(text.as_bytes(), MeshFormat::Obj).expect("groups"),
        mesh
    );
}

#[test]
fn obj_problems_are_located() {
    let v = "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 0 3 0\n";
    let located = |body: &str| err(format!("{v}{body}").as_bytes(), MeshFormat::Obj).to_string();
    assert!(located("f 1 2 3 4\nf 1 3 2 5\n").starts_with("t.obj:7: face is self-intersecting"));
    assert!(located("f 1 3 2 5 4\n").starts_with("t.obj:6: face is self-intersecting"));
    assert!(located("f 1 2 3 1\n").starts_with("t.obj:6: face vertices 1 and 4 coincide"));
    assert!(located("v 1 2 inf\n").starts_with("t.obj:6: coordinate 'inf' is not a finite"));
    // A forward reference across objects, which tobj rejects.
    let forward = "o a\nv 0 0 0\nv 1 0 0\nf 1 2 3\no b\nv 0 1 0\nf 1 2 3\n";
    let e = err(forward.as_bytes(), MeshFormat::Obj).to_string();
    assert!(
        e.starts_with("t.obj:4: face index 3 refers to a later line"),
        "{e}"
    );
}

#[test]
fn ply_with_extra_properties_and_elements() {
    let expected = IndexedMesh::new(
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    assert_eq!(read(EXTRA_PLY, MeshFormat::Ply).expect("ascii"), expected);
    for big_endian in [false, true] {
        let bytes = extra_ply_binary(big_endian);
        assert_eq!(read(&bytes, MeshFormat::Ply).expect("binary"), expected);
    }
}

/// The content of `extra.ply` in a binary encoding.
fn extra_ply_binary(big_endian: bool) -> Vec<u8> {
    let text = std::str::from_utf8(EXTRA_PLY).expect("utf8");
    let (header, _) = text.split_once("end_header\n").expect("header");
    let format = if big_endian {
        "binary_big_endian"
    } else {
        "binary_little_endian"
    };
    let mut out = header.replace("ascii", format).into_bytes();
    out.extend_from_slice(b"end_header\n");
    let f32s = |out: &mut Vec<u8>, values: &[f32]| {
        for v in values {
            out.extend(if big_endian {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            });
        }
    };
    let i32s = |out: &mut Vec<u8>, values: &[i32]| {
        for v in values {
            out.extend(if big_endian {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            });
        }
    };
    // vertex: x y (float) red (uchar) z (float) extra_list (uchar count, floats)
    for (x, y, red, z, extra) in [
        (0.0, 0.0, 255, 0.0, vec![]),
        (1.0, 0.0, 0, 0.0, vec![0.5, 0.25]),
        (1.0, 1.0, 7, 0.0, vec![9.0]),
        (0.0, 1.0, 0, 0.0, vec![]),
    ] {
        f32s(&mut out, &[x, y]);
        out.push(red);
        f32s(&mut out, &[z]);
        out.push(extra.len() as u8);
        f32s(&mut out, &extra);
    }
    // material: shine (float), tags (uchar count, ints)
    f32s(&mut out, &[0.5]);
    out.push(2);
    i32s(&mut out, &[1, 7]);
    f32s(&mut out, &[0.7]);
    out.push(0);
    // face: flags (uchar), vertex_indices (uchar count, ints), quality (float)
    for (flags, indices, quality) in [(1, [0, 1, 2], 0.5), (2, [0, 2, 3], 1.5)] {
        out.push(flags);
        out.push(3);
        i32s(&mut out, &indices);
        f32s(&mut out, &[quality]);
    }
    // edge: two ints
    i32s(&mut out, &[0, 2]);
    out
}

#[test]
fn ply_problems_are_located() {
    let ply = |body: &str| {
        format!(
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
             property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
             end_header\n{body}"
        )
    };
    let e = |body: &str| err(ply(body).as_bytes(), MeshFormat::Ply).to_string();
    assert_eq!(
        e("0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
        "t.ply:13: face index 3 out of range (the file has 3 vertices)"
    );
    assert!(e("0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n").starts_with("t.ply:11: coordinate NaN"));
    assert!(e("0 0 0\n1 0 0\n0 1 0\n").contains("unexpected end of file"));
    assert!(e("0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n").starts_with("t.ply:14: unexpected data"));
    assert!(e("0 0 0\n1 0 0\n0 1 0\n2 0 1\n").starts_with("t.ply:13: face has 2 vertices"));
    let no_z =
        "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nend_header\n";
    assert!(
        err(no_z.as_bytes(), MeshFormat::Ply)
            .to_string()
            .starts_with("t.ply:3: vertex element has no 'z'")
    );
    let mut binary = encoded(&cube(), MeshFormat::Ply, Encoding::Binary);
    let len = binary.len();
    binary.truncate(len - 3);
    assert!(matches!(
        err(&binary, MeshFormat::Ply).location(),
        Some(Location::Byte(_))
    ));
}

#[test]
fn off_with_comments_and_colors() {
    let mesh = read(COMMENTED_OFF, MeshFormat::Off).expect("off");
    assert_eq!(mesh.positions.len(), 4);
    assert_eq!(mesh.triangles, [[0, 1, 2], [0, 2, 3]]);
    let e = |text: &str| err(text.as_bytes(), MeshFormat::Off).to_string();
    assert!(
        e("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n")
            .starts_with("t.off:6: face index 5 out of range")
    );
    assert!(e("OFF\n3 1 0\n0 0 0\n1 nan 0\n").starts_with("t.off:4: coordinate 'nan'"));
    assert!(e("OFF 3 1\n0 0 0\n").starts_with("t.off:2: unexpected end of file"));
    assert!(e("PLY\n").starts_with("t.off:1: not an OFF file"));
    let pentagon = "OFF 5 1 0\n0 0 0\n2 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4\n";
    assert_eq!(
        read(pentagon.as_bytes(), MeshFormat::Off)
            .expect("pentagon")
            .triangle_count(),
        3
    );
}

#[test]
fn nan_coordinates_are_rejected_in_every_format() {
    let mut mesh = octahedron();
    mesh.positions[3].z = 0.125;
    for (format, encoding) in ALL {
        let bytes = encoded(&mesh, format, encoding);
        let nan_bytes = nan_variant(&bytes, format, encoding);
        let e = err(&nan_bytes, format);
        assert!(
            e.location().is_some() && e.to_string().contains("finite"),
            "{format:?}: {e}"
        );
    }
}

/// `bytes` with the coordinate 0.125 replaced by NaN.
fn nan_variant(bytes: &[u8], format: MeshFormat, encoding: Encoding) -> Vec<u8> {
    let replace = |from: &[u8], to: &[u8]| {
        let at = bytes
            .windows(from.len())
            .position(|w| w == from)
            .expect("coordinate present");
        [&bytes[..at], to, &bytes[at + from.len()..]].concat()
    };
    match (format, encoding) {
        (MeshFormat::Stl, Encoding::Binary) => {
            replace(&0.125f32.to_le_bytes(), &f32::NAN.to_le_bytes())
        }
        (MeshFormat::Ply, Encoding::Binary) => {
            replace(&0.125f64.to_le_bytes(), &f64::NAN.to_le_bytes())
        }
        (MeshFormat::Stl, _) => replace(b"1.25e-1", b"NaN"),
        _ => replace(b"0.125", b"NaN"),
    }
}

/// A small deterministic pseudo-random generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    fn float(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Reads `bytes` as every format: no panic, and errors or meshes must be well-formed.
fn read_as_everything(bytes: &[u8]) {
    for format in [
        MeshFormat::Stl,
        MeshFormat::Obj,
        MeshFormat::Ply,
        MeshFormat::Off,
    ] {
        let name = format!("fuzz.{}", format.extension());
        match read_mesh_bytes(bytes, format, &name) {
            Ok(mesh) => {
                assert!(mesh.indices_in_range());
                assert!(mesh.positions.iter().all(|p| p.is_finite()));
            }
            Err(e) => {
                let message = e.to_string();
                assert!(message.starts_with(&name), "{message}");
                assert!(!message.contains('\n'), "{message:?}");
            }
        }
    }
}

#[test]
fn random_bytes_never_panic() {
    let mut rng = Rng(0x5EED_1234_ABCD_0001);
    let prefixes: [&[u8]; 9] = [
        b"",
        b"solid ",
        b"solid x\nfacet normal 0 0 1\nouter loop\nvertex ",
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
        b"ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty \
          float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n\
          end_header\n",
        b"ply\nformat binary_big_endian 1.0\nelement face 4000000000\nproperty list uint uint \
          vertex_indices\nelement vertex 9\nproperty double x\nproperty double y\nproperty \
          double z\nend_header\n",
        b"OFF\n",
        b"OFF 4000000000 4000000000 0\n",
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf ",
    ];
    for round in 0..600u32 {
        let len = rng.below(if round.is_multiple_of(10) { 4000 } else { 300 });
        let mut bytes = rng.pick(&prefixes).to_vec();
        bytes.extend((0..len).map(|_| {
            let r = rng.next();
            // Mostly printable so that text parsers get further.
            if r.is_multiple_of(4) {
                (r >> 8) as u8
            } else {
                b" 0123456789.-e\n/#"[(r >> 8) as usize % 17]
            }
        }));
        read_as_everything(&bytes);
    }
}

#[test]
fn stl_sized_random_bytes_never_panic() {
    let mut rng = Rng(99);
    for count in 0..40u32 {
        let mut bytes: Vec<u8> = (0..84 + 50 * count as usize)
            .map(|_| rng.next() as u8)
            .collect();
        bytes[80..84].copy_from_slice(&count.to_le_bytes());
        read_as_everything(&bytes);
    }
}

#[test]
fn obj_token_soup_never_panics() {
    let keywords = [
        "v", "vt", "vn", "f", "l", "o", "g", "usemtl", "mtllib", "#", "p", "s", "f",
    ];
    let tokens = [
        "1",
        "2",
        "3",
        "4",
        "-1",
        "-2",
        "-7",
        "0",
        "1/1",
        "2//1",
        "3/1/1",
        "1/-5",
        "/",
        "//",
        "/1",
        "1/2/3/4",
        "1/2/3/",
        "-9223372036854775808",
        "9223372036854775807",
        "2/9223372036854775807",
        "1//-9223372036854775808",
        "nan",
        "inf",
        "1e39",
        "-0",
        "0.5",
        "x",
        "é",
        "1e-45",
    ];
    let mut rng = Rng(42);
    for _ in 0..800 {
        // Valid vertices first (most of the time), so that many faces get to tobj and beyond.
        let mut text = String::new();
        for _ in 0..rng.below(12) {
            let [x, y, z] = [rng.below(3), rng.below(3), rng.below(3)];
            text += &format!("v {x} {y} {z}\nvt 0 0\n");
        }
        for _ in 0..rng.below(12) {
            text += *rng.pick(&keywords);
            for _ in 0..rng.below(7) {
                text.push(' ');
                text += *rng.pick(&tokens);
            }
            text.push('\n');
        }
        read_as_everything(text.as_bytes());
    }
}

#[test]
fn mutated_valid_files_never_panic() {
    let mut rng = Rng(2024);
    let mut sources: Vec<Vec<u8>> = ALL
        .iter()
        .map(|&(format, encoding)| encoded(&cube(), format, encoding))
        .collect();
    sources.extend([FACES_OBJ, EXTRA_PLY, COMMENTED_OFF].map(<[u8]>::to_vec));
    sources.push(extra_ply_binary(true));
    for _ in 0..500 {
        let mut bytes = rng.pick(&sources).clone();
        match rng.below(4) {
            0 => bytes.truncate(rng.below(bytes.len() + 1)),
            1 => {
                for _ in 0..1 + rng.below(8) {
                    let at = rng.below(bytes.len());
                    bytes[at] = rng.next() as u8;
                }
            }
            2 => {
                let at = rng.below(bytes.len());
                let digit = *rng.pick(b"0123456789-9e");
                bytes.insert(at, digit);
            }
            _ => {
                let from = rng.below(bytes.len());
                let to = (from + rng.below(64)).min(bytes.len());
                let chunk = bytes[from..to].to_vec();
                let at = rng.below(bytes.len());
                bytes.splice(at..at, chunk);
            }
        }
        read_as_everything(&bytes);
    }
}

#[test]
fn random_polygon_faces_are_triangulated_or_rejected() {
    let mut rng = Rng(314);
    let mut triangulated = 0;
    for _ in 0..400 {
        let vertices = 3 + rng.below(10);
        let mut text = String::new();
        for _ in 0..vertices {
            let [x, y] = [rng.below(4), rng.below(4)];
            text += &format!("v {x} {y} {}\n", rng.below(2) as f64 * 1e-3);
        }
        let corners = 3 + rng.below(6);
        text += "f";
        for _ in 0..corners {
            text += &format!(" {}", 1 + rng.below(vertices));
        }
        text.push('\n');
        read_as_everything(text.as_bytes());
        if let Ok(mesh) = read(text.as_bytes(), MeshFormat::Obj) {
            assert_eq!(mesh.triangle_count(), corners - 2);
            triangulated += 1;
        }
    }
    assert!(
        triangulated > 40,
        "only {triangulated} random faces were valid"
    );
}

/// Errors about a file that is not of the expected format never quote its content (a `mesh`
/// node may point at a link to any file), and quoted tokens never carry control characters.
#[test]
fn foreign_content_is_never_quoted() {
    let secret = b"root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1:daemon:/usr/sbin\n";
    for format in [
        MeshFormat::Stl,
        MeshFormat::Obj,
        MeshFormat::Ply,
        MeshFormat::Off,
    ] {
        let text = match read_mesh_bytes(secret, format, "x") {
            Err(e) => e.to_string(),
            // OBJ ignores lines it does not know: no faces, nothing quoted.
            Ok(mesh) if format == MeshFormat::Obj && mesh.triangles.is_empty() => continue,
            Ok(mesh) => panic!("{format:?}: read as {mesh:?}"),
        };
        assert!(
            !text.contains("root") && !text.contains("daemon"),
            "{format:?}: {text}"
        );
    }
    // A text file that happens to start with `solid` is not quoted either.
    let e = read_mesh_bytes(
        b"solid state\nsecret words here\n",
        MeshFormat::Stl,
        "x.stl",
    )
    .expect_err("not an STL");
    assert!(!e.to_string().contains("secret"), "{e}");
    // Inside a recognised file tokens are quoted, with control characters escaped.
    let stl = b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 \x1b[31m\n";
    let e = read_mesh_bytes(stl, MeshFormat::Stl, "t.stl").expect_err("bad number");
    let text = e.to_string();
    assert!(text.contains("\\u{1b}[31m"), "{text}");
    assert!(!text.chars().any(char::is_control), "{text:?}");
}

/// The parallel binary STL reader gives the serial reader's mesh: a tessellated sphere (shared
/// corners, signed zeros on its axes) written as binary STL.
#[test]
fn parallel_binary_stl_matches_the_serial_reader() {
    let sphere = solidkit_kernel::tessellate::sphere(1.0, 40, 21)
        .unwrap()
        .mesh;
    let mesh = IndexedMesh::new(sphere.positions, sphere.triangles);
    let bytes = encoded(&mesh, MeshFormat::Stl, Encoding::Binary);
    let count = u32::try_from(mesh.triangles.len()).unwrap();
    let parallel = stl::read_binary(&bytes, count, "s.stl").unwrap();
    let serial = stl::read_binary_serial(&bytes, count, "s.stl").unwrap();
    assert_eq!(parallel, serial);
    assert!(parallel.positions.len() < 3 * parallel.triangles.len() / 2);
}

/// The resolver's failures are typed across the crate boundary: the kind says which request
/// failed and how, and the reader's own error is reachable for downcasting.
#[test]
fn resolver_errors_carry_kind_and_reader_error() {
    use solidkit_kernel::json::MeshResolver;
    use solidkit_kernel::primitive::ResolveKind;
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("bad.off"), "OFF\n3 1 0\n0 0 0\n").expect("write");
    let resolver = super::FileMeshResolver::new(dir.path());

    let missing = resolver.load("missing.stl").expect_err("no such file");
    assert_eq!(missing.kind(), ResolveKind::File);
    assert!(missing.inner().downcast_ref::<MeshIoError>().is_some());

    let escape = resolver.read_file("../outside.png").expect_err("confined");
    assert_eq!(escape.kind(), ResolveKind::File);

    let bad = resolver.load("bad.off").expect_err("truncated OFF");
    assert_eq!(bad.kind(), ResolveKind::Format);
    let inner = bad
        .inner()
        .downcast_ref::<MeshIoError>()
        .expect("reader error");
    assert_eq!(inner.to_string(), bad.to_string());
}
