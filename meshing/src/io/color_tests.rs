//! Coloured files read back: every triangle of `difference() { color("red") cube(10, center =
//! true); color("blue") sphere(6.5); }` has its colour in 3MF, PLY and GLB, the readers see the
//! same mesh, and uncoloured writes are unchanged.

use super::unzip::Archive;
use super::{Encoding, MeshFormat, encode, encode_colored, read_mesh_bytes};
use crate::IndexedMesh;
use crate::colors::tests::{check_cube_minus_sphere, cube_minus_sphere, meshed};
use crate::colors::{DEFAULT_COLOR, FaceColors};

fn bytes(mesh: &IndexedMesh, c: Option<&FaceColors>, f: MeshFormat, e: Encoding) -> Vec<u8> {
    let mut out = Vec::new();
    encode_colored(&mut out, mesh, c, f, e).unwrap();
    out
}

/// Per-triangle colours of a 3MF model part written by solidkit.
fn threemf_colors(file: &[u8]) -> Vec<[u8; 4]> {
    let zip = Archive::open(file, "t.3mf").unwrap();
    let model = zip
        .read(zip.find(super::THREEMF_MODEL_PATH).unwrap(), 1 << 30)
        .unwrap();
    let text = std::str::from_utf8(&model).unwrap();
    let attr = |line: &str, key: &str| -> Option<String> {
        let at = line.find(&format!(" {key}=\""))? + key.len() + 3;
        Some(line[at..].split('"').next()?.to_string())
    };
    let bases: Vec<[u8; 4]> = text
        .lines()
        .filter(|l| l.contains("<base "))
        .map(|l| {
            let hex = attr(l, "displaycolor").unwrap();
            let b = |i: usize| u8::from_str_radix(&hex[1 + 2 * i..3 + 2 * i], 16).unwrap();
            [b(0), b(1), b(2), b(3)]
        })
        .collect();
    let object = text.lines().find(|l| l.contains("<object ")).unwrap();
    let default: usize = attr(object, "pindex").unwrap().parse().unwrap();
    text.lines()
        .filter(|l| l.contains("<triangle "))
        .map(|l| bases[attr(l, "p1").map_or(default, |p| p.parse().unwrap())])
        .collect()
}

/// Per-face colours of an ASCII PLY written by solidkit (the last four numbers of a face line).
fn ply_colors(file: &[u8]) -> Vec<[u8; 4]> {
    let text = std::str::from_utf8(file).unwrap();
    let body = text.split("end_header\n").nth(1).unwrap();
    body.lines()
        .filter(|l| l.starts_with("3 ") && l.split(' ').count() == 8)
        .map(|l| {
            let v: Vec<u8> = l.split(' ').skip(4).map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

/// The triangles of a GLB (in the file's order) with their material's colour.
fn glb_colors(file: &[u8]) -> (Vec<[u32; 3]>, Vec<Option<[f64; 4]>>) {
    let json_len = u32::from_le_bytes(file[12..16].try_into().unwrap()) as usize;
    let v: serde_json::Value = serde_json::from_slice(&file[20..20 + json_len]).unwrap();
    let bin = &file[20 + json_len + 8..];
    let (mut tris, mut colors) = (Vec::new(), Vec::new());
    for p in v["meshes"][0]["primitives"].as_array().unwrap() {
        let acc = &v["accessors"][p["indices"].as_u64().unwrap() as usize];
        let view = &v["bufferViews"][acc["bufferView"].as_u64().unwrap() as usize];
        let start = view["byteOffset"].as_u64().unwrap() as usize;
        let n = acc["count"].as_u64().unwrap() as usize;
        let idx: Vec<u32> = (0..n)
            .map(|k| u32::from_le_bytes(bin[start + 4 * k..start + 4 * k + 4].try_into().unwrap()))
            .collect();
        let color = p.get("material").map(|m| {
            let f = &v["materials"][m.as_u64().unwrap() as usize]["pbrMetallicRoughness"]
                ["baseColorFactor"];
            [0, 1, 2, 3].map(|i| f[i].as_f64().unwrap())
        });
        for t in idx.chunks(3) {
            tris.push([t[0], t[1], t[2]]);
            colors.push(color);
        }
    }
    (tris, colors)
}

#[test]
fn threemf_ply_and_glb_carry_the_colours_and_read_back_as_one_mesh() {
    let solid = cube_minus_sphere();
    let m = meshed(&solid);
    let c = m.face_colors(&solid).unwrap();
    let mesh = &m.mesh;
    let threemf = bytes(mesh, Some(&c), MeshFormat::ThreeMf, Encoding::Binary);
    let per = threemf_colors(&threemf);
    check_cube_minus_sphere(mesh, |t| per[t]);
    let ply = bytes(mesh, Some(&c), MeshFormat::Ply, Encoding::Ascii);
    let per = ply_colors(&ply);
    check_cube_minus_sphere(mesh, |t| per[t]);
    let glb = bytes(mesh, Some(&c), MeshFormat::Glb, Encoding::Binary);
    let (tris, per) = glb_colors(&glb);
    assert_eq!(per.iter().filter(|c| c.is_none()).count(), 0);
    let regrouped = IndexedMesh::new(mesh.positions.clone(), tris);
    check_cube_minus_sphere(&regrouped, |t| {
        per[t].unwrap().map(|x| (x * 255.0).round() as u8)
    });
    // the readers see the same mesh (GLB's triangles grouped by colour, positions in f32)
    for (format, file) in [
        (MeshFormat::ThreeMf, &threemf),
        (MeshFormat::Glb, &glb),
        (MeshFormat::Ply, &ply),
        (
            MeshFormat::Ply,
            &bytes(mesh, Some(&c), MeshFormat::Ply, Encoding::Binary),
        ),
    ] {
        let back = read_mesh_bytes(file, format, "m").unwrap();
        assert_eq!(back.triangles.len(), mesh.triangles.len(), "{format:?}");
        // the same triangles, in any order and numbering (centroids to 1e-4)
        let keys = |m: &IndexedMesh| {
            let mut k: Vec<[i64; 3]> = (0..m.triangles.len())
                .map(|t| {
                    crate::colors::tests::centroid(m, t)
                        .to_array()
                        .map(|x| (x * 1e4).round() as i64)
                })
                .collect();
            k.sort_unstable();
            k
        };
        assert!(keys(&back) == keys(mesh), "{format:?}: other triangles");
    }
    // without colours the writers write what they always wrote
    for format in [MeshFormat::ThreeMf, MeshFormat::Glb, MeshFormat::Ply] {
        let mut plain = Vec::new();
        encode(&mut plain, mesh, format, Encoding::Binary).unwrap();
        assert_eq!(plain, bytes(mesh, None, format, Encoding::Binary));
        assert_ne!(plain, bytes(mesh, Some(&c), format, Encoding::Binary));
    }
}

#[test]
fn one_colour_is_an_object_property_and_uncoloured_triangles_get_the_default() {
    let tri = IndexedMesh::new(
        vec![
            glam::DVec3::ZERO,
            glam::DVec3::X,
            glam::DVec3::Y,
            glam::DVec3::Z,
        ],
        vec![[0, 1, 2], [0, 1, 3]],
    );
    let one = FaceColors {
        palette: vec![[10, 20, 30, 128]],
        faces: vec![0, 0],
    };
    let file = bytes(&tri, Some(&one), MeshFormat::ThreeMf, Encoding::Binary);
    assert_eq!(threemf_colors(&file), vec![[10, 20, 30, 128]; 2]);
    let zip = Archive::open(&file, "t").unwrap();
    let model = zip
        .read(zip.find(super::THREEMF_MODEL_PATH).unwrap(), 1 << 20)
        .unwrap();
    assert!(
        !String::from_utf8_lossy(&model).contains("p1="),
        "object-level pid"
    );
    let (_, glb) = glb_colors(&bytes(&tri, Some(&one), MeshFormat::Glb, Encoding::Binary));
    assert!(glb.iter().all(|c| c.unwrap()[3] == 128.0 / 255.0));
    let glb = bytes(&tri, Some(&one), MeshFormat::Glb, Encoding::Binary);
    assert!(String::from_utf8_lossy(&glb).contains("\"alphaMode\":\"BLEND\""));
    let half = FaceColors {
        palette: vec![[1, 2, 3, 255]],
        faces: vec![0, FaceColors::NONE],
    };
    let file = bytes(&tri, Some(&half), MeshFormat::ThreeMf, Encoding::Binary);
    assert_eq!(threemf_colors(&file), vec![[1, 2, 3, 255], DEFAULT_COLOR]);
    let file = bytes(&tri, Some(&half), MeshFormat::Ply, Encoding::Ascii);
    assert_eq!(ply_colors(&file), vec![[1, 2, 3, 255], DEFAULT_COLOR]);
    let (_, glb) = glb_colors(&bytes(&tri, Some(&half), MeshFormat::Glb, Encoding::Binary));
    assert_eq!(glb.iter().filter(|c| c.is_none()).count(), 1);
}

#[test]
fn off_carries_a_colour_after_each_faces_indices() {
    let solid = cube_minus_sphere();
    let m = meshed(&solid);
    let c = m.face_colors(&solid).unwrap();
    let mesh = &m.mesh;
    let off = bytes(mesh, Some(&c), MeshFormat::Off, Encoding::Ascii);
    let text = std::str::from_utf8(&off).unwrap();
    // after "OFF", the comment, the counts and the vertices: "3 i j k r g b a" per face
    let faces: Vec<Vec<u32>> = text
        .lines()
        .skip(3 + mesh.positions.len())
        .map(|l| l.split(' ').map(|w| w.parse().unwrap()).collect())
        .collect();
    assert_eq!(faces.len(), mesh.triangles.len());
    for (f, t) in faces.iter().zip(&mesh.triangles) {
        assert_eq!(f.len(), 8);
        assert_eq!(f[..4], [3, t[0], t[1], t[2]]);
    }
    check_cube_minus_sphere(mesh, |t| {
        faces[t][4..]
            .iter()
            .map(|&x| x as u8)
            .collect::<Vec<_>>()
            .try_into()
            .unwrap()
    });
    // the reader skips the colours: the same mesh, exactly
    let back = read_mesh_bytes(&off, MeshFormat::Off, "m").unwrap();
    assert_eq!(back.positions, mesh.positions);
    assert_eq!(back.triangles, mesh.triangles);
    // uncoloured triangles get the default; no colours: the plain file
    let none = FaceColors {
        palette: vec![],
        faces: vec![FaceColors::NONE; mesh.triangles.len()],
    };
    let off = bytes(mesh, Some(&none), MeshFormat::Off, Encoding::Ascii);
    let [r, g, b, a] = DEFAULT_COLOR;
    let last = std::str::from_utf8(&off)
        .unwrap()
        .lines()
        .last()
        .unwrap()
        .to_string();
    assert!(last.ends_with(&format!(" {r} {g} {b} {a}")), "{last}");
    let mut plain = Vec::new();
    encode(&mut plain, mesh, MeshFormat::Off, Encoding::Ascii).unwrap();
    assert_eq!(plain, bytes(mesh, None, MeshFormat::Off, Encoding::Ascii));
}
