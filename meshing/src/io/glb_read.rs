//! glTF 2.0 binary (`.glb`) input: the 12-byte header, the JSON chunk (see
//! [`gltf_json`](super::gltf_json)) and the BIN chunk → one [`IndexedMesh`].
//!
//! Every primitive of every mesh reached from the default scene (`scene`, else the first scene,
//! else every node that is no node's child) is read: triangles (mode 4), triangle strips (5)
//! and fans (6); points and lines are skipped. Positions come from the `POSITION` accessor
//! (`FLOAT` `VEC3`, interleaved views allowed), indices from an unsigned byte, short or int
//! `SCALAR` accessor (none: 0, 1, 2, ...). Each node's matrix or translation–rotation–scale is
//! applied down the hierarchy, then glTF's +Y up is turned into solidkit's +Z up,
//! `(x, y, z) ↦ (x, −z, y)`, the inverse of what the [writer](super::glb) puts in its node, so
//! a file solidkit wrote reads back with its own coordinates (the 3×3 part of the final
//! transform is snapped to exact 0 and ±1 within 4 ulps, so such rotations are exact). Each
//! primitive keeps its own vertices (nothing is welded: `check --weld 0` joins a file split at
//! normal or texture seams). Only the BIN chunk is read: external and data-URI buffers and
//! sparse accessors are refused.

use glam::{DAffine3, DMat3, DMat4, DQuat, DVec3};

use super::gltf_json::{Accessor, Gltf, Node};
use super::threemf_model::MAX_ELEMENTS;
use super::{Location, MeshIoError};
use crate::IndexedMesh;

/// `glTF`.
const MAGIC: &[u8; 4] = b"glTF";

/// Reads a GLB file.
pub(super) fn read(bytes: &[u8], name: &str) -> Result<IndexedMesh, MeshIoError> {
    let at = |offset: usize, message: String| {
        MeshIoError::parse(name, Location::Byte(offset as u64), message)
    };
    let le32 = |offset: usize| -> Option<usize> {
        let b = bytes.get(offset..offset.checked_add(4)?)?;
        Some(u32::from_le_bytes(b.try_into().ok()?) as usize)
    };
    if bytes.get(..4) != Some(MAGIC) {
        return Err(at(0, "not a GLB file (no 'glTF' magic)".into()));
    }
    match le32(4) {
        Some(2) => {}
        Some(v) => {
            return Err(at(
                4,
                format!("glTF container version {v} (only 2 is read)"),
            ));
        }
        None => return Err(at(bytes.len(), "truncated header".into())),
    }
    let total = le32(8).ok_or_else(|| at(bytes.len(), "truncated header".into()))?;
    if total > bytes.len() {
        return Err(at(
            bytes.len(),
            format!("truncated: the header says {total} bytes"),
        ));
    }
    let bytes = &bytes[..total];
    let (json, bin_at) = chunk(bytes, 12, *b"JSON").map_err(|(o, m)| at(o, m))?;
    let bin = if bin_at + 8 <= bytes.len() {
        chunk(bytes, bin_at, *b"BIN\0")
            .map_err(|(o, m)| at(o, m))?
            .0
    } else {
        &[][..]
    };
    let gltf: Gltf = serde_json::from_slice(json).map_err(|e| {
        let offset = 20 + json_offset(json, e.line(), e.column());
        let text = e.to_string();
        let message = text.split(" at line ").next().unwrap_or(&text);
        at(offset, format!("JSON chunk: {message}"))
    })?;
    Reader {
        gltf: &gltf,
        bin,
        name,
    }
    .scene()
}

/// The content of the chunk at `offset`, which must be of `kind`, and the offset after it.
fn chunk(bytes: &[u8], offset: usize, kind: [u8; 4]) -> Result<(&[u8], usize), (usize, String)> {
    let shown = String::from_utf8_lossy(&kind)
        .trim_end_matches('\0')
        .to_string();
    let header = bytes
        .get(offset..offset + 8)
        .ok_or((bytes.len(), format!("truncated before the {shown} chunk")))?;
    if header[4..8] != kind {
        return Err((offset + 4, format!("expected the {shown} chunk")));
    }
    let len = u32::from_le_bytes([header[0], header[1], header[2], header[3]]) as usize;
    let data = bytes.get(offset + 8..offset + 8 + len).ok_or((
        bytes.len(),
        format!("truncated {shown} chunk ({len} bytes declared)"),
    ))?;
    Ok((data, offset + 8 + len))
}

/// The byte offset of 1-based `line` and `column` in `text`.
fn json_offset(text: &[u8], line: usize, column: usize) -> usize {
    let start = text
        .iter()
        .enumerate()
        .filter(|&(_, &b)| b == b'\n')
        .nth(line.saturating_sub(2))
        .map_or(0, |(i, _)| i + 1);
    if line <= 1 {
        column.saturating_sub(1)
    } else {
        start + column.saturating_sub(1)
    }
}

/// glTF +Y up → solidkit +Z up.
const Y_UP_TO_Z_UP: DMat3 = DMat3::from_cols(DVec3::X, DVec3::Z, DVec3::NEG_Y);

/// The document and its binary chunk.
struct Reader<'a> {
    gltf: &'a Gltf,
    bin: &'a [u8],
    name: &'a str,
}

impl Reader<'_> {
    fn err(&self, message: String) -> MeshIoError {
        MeshIoError::invalid(self.name, format!("JSON chunk: {message}"))
    }

    /// Every mesh of the default scene, transformed.
    fn scene(&self) -> Result<IndexedMesh, MeshIoError> {
        let g = self.gltf;
        let roots: Vec<usize> = match g.scene.or((!g.scenes.is_empty()).then_some(0)) {
            Some(s) => g
                .scenes
                .get(s)
                .ok_or_else(|| self.err(format!("scene {s} does not exist")))?
                .nodes
                .clone(),
            None => {
                let mut child = vec![false; g.nodes.len()];
                g.nodes.iter().flat_map(|n| &n.children).for_each(|&c| {
                    if let Some(flag) = child.get_mut(c) {
                        *flag = true;
                    }
                });
                (0..g.nodes.len()).filter(|&n| !child[n]).collect()
            }
        };
        let mut seen = vec![false; g.nodes.len()];
        let mut stack: Vec<(usize, DAffine3)> = roots
            .iter()
            .rev()
            .map(|&n| (n, DAffine3::IDENTITY))
            .collect();
        let mut draws: Vec<(usize, usize, DAffine3)> = Vec::new();
        while let Some((n, parent)) = stack.pop() {
            let node = g
                .nodes
                .get(n)
                .ok_or_else(|| self.err(format!("node {n} does not exist")))?;
            if std::mem::replace(&mut seen[n], true) {
                return Err(self.err(format!("nodes[{n}] is reached twice (not a tree)")));
            }
            let world = parent * local(node).map_err(|m| self.err(format!("nodes[{n}]: {m}")))?;
            if let Some(m) = node.mesh {
                draws.push((n, m, to_z_up(world)));
            }
            stack.extend(node.children.iter().rev().map(|&c| (c, world)));
        }
        // What the scene expands to, from the accessors' counts, before anything is read: a
        // small mesh drawn by many nodes must not grow into gigabytes.
        let total = draws.iter().fold(0usize, |sum, &(_, m, _)| {
            sum.saturating_add(self.declared_elements(m))
        });
        if total > MAX_ELEMENTS {
            return Err(self.err(format!(
                "the scene expands to more than {MAX_ELEMENTS} vertices and triangles"
            )));
        }
        let mut mesh = IndexedMesh::default();
        for (n, m, t) in draws {
            self.add_mesh(&mut mesh, m, &t)
                .map_err(|e| self.err(format!("nodes[{n}]: meshes[{m}]{e}")))?;
        }
        Ok(mesh)
    }

    /// Positions plus index count of mesh `m`'s surface primitives, as the accessors declare
    /// them (an upper bound of its vertices and triangles; 0 for what does not exist).
    fn declared_elements(&self, m: usize) -> usize {
        let count = |a: Option<usize>| {
            a.and_then(|a| self.gltf.accessors.get(a))
                .map_or(0, |acc| usize::try_from(acc.count).unwrap_or(usize::MAX))
        };
        self.gltf.meshes.get(m).map_or(0, |mesh| {
            mesh.primitives
                .iter()
                .filter(|p| matches!(p.mode, 4..=6))
                .fold(0usize, |sum, p| {
                    let positions = count(p.attributes.get("POSITION").copied());
                    let indices = p.indices.map_or(positions, |i| count(Some(i)));
                    sum.saturating_add(positions).saturating_add(indices)
                })
        })
    }

    /// Appends every primitive of mesh `m`; errors start with the primitive's path.
    fn add_mesh(&self, out: &mut IndexedMesh, m: usize, t: &DAffine3) -> Result<(), String> {
        let mesh = self.gltf.meshes.get(m).ok_or(" does not exist")?;
        for (p, prim) in mesh.primitives.iter().enumerate() {
            let fail = |e: String| format!(".primitives[{p}]: {e}");
            if !matches!(prim.mode, 4..=6) {
                if prim.mode > 6 {
                    return Err(fail(format!("unknown mode {}", prim.mode)));
                }
                continue;
            }
            let &pa = prim
                .attributes
                .get("POSITION")
                .ok_or_else(|| fail("no POSITION".into()))?;
            let positions = self.positions(pa).map_err(fail)?;
            let indices = match prim.indices {
                Some(i) => self.indices(i).map_err(fail)?,
                None => (0..positions.len() as u32).collect(),
            };
            let triangles = assemble(&indices, prim.mode, positions.len()).map_err(fail)?;
            let count =
                out.positions.len() + positions.len() + out.triangles.len() + triangles.len();
            if count > MAX_ELEMENTS {
                return Err(fail(format!(
                    "more than {MAX_ELEMENTS} vertices and triangles in all"
                )));
            }
            let base = out.positions.len() as u32;
            for q in positions {
                let q = t.transform_point3(q);
                if !q.is_finite() {
                    return Err(fail("a position is not finite once transformed".into()));
                }
                out.positions.push(q);
            }
            out.triangles
                .extend(triangles.iter().map(|t| t.map(|v| v + base)));
        }
        Ok(())
    }

    /// The bytes of accessor `a`'s elements: the accessor, its elements' stride and the view.
    fn view(&self, a: usize, size: u64) -> Result<(&Accessor, u64, &[u8]), String> {
        let g = self.gltf;
        let acc = g
            .accessors
            .get(a)
            .ok_or(format!("accessor {a} does not exist"))?;
        let fail = |m: &str| format!("accessors[{a}]: {m}");
        if acc.sparse.is_some() {
            return Err(fail("sparse accessors are not supported"));
        }
        let v = acc.buffer_view.ok_or_else(|| fail("no bufferView"))?;
        let view = g
            .buffer_views
            .get(v)
            .ok_or_else(|| fail("its bufferView does not exist"))?;
        let buffer = g
            .buffers
            .get(view.buffer)
            .ok_or_else(|| fail("its buffer does not exist"))?;
        if buffer.uri.is_some() || view.buffer != 0 {
            return Err(fail(
                "external and data-URI buffers are not read (only the BIN chunk)",
            ));
        }
        let bytes = view
            .byte_offset
            .checked_add(view.byte_length)
            .filter(|&end| end <= self.bin.len() as u64 && end <= buffer.byte_length)
            .map(|end| &self.bin[view.byte_offset as usize..end as usize])
            .ok_or_else(|| fail("its bufferView runs past the BIN chunk"))?;
        let stride = view.byte_stride.unwrap_or(size);
        let needed = match acc.count {
            0 => Some(0),
            n => (n - 1)
                .checked_mul(stride)
                .and_then(|x| x.checked_add(size))
                .and_then(|x| x.checked_add(acc.byte_offset)),
        };
        if stride < size || needed.is_none_or(|n| n > bytes.len() as u64) {
            return Err(fail("its elements run past the bufferView"));
        }
        Ok((acc, stride, bytes))
    }

    /// The positions of `FLOAT` `VEC3` accessor `a`.
    fn positions(&self, a: usize) -> Result<Vec<DVec3>, String> {
        let (acc, stride, bytes) = self.view(a, 12)?;
        if acc.component_type != 5126 || acc.kind != "VEC3" {
            return Err(format!("accessors[{a}]: POSITION must be FLOAT VEC3"));
        }
        let f = |at: usize| {
            f32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
        };
        let mut out = Vec::with_capacity(acc.count as usize);
        for i in 0..acc.count {
            let at = (acc.byte_offset + i * stride) as usize;
            let p = DVec3::new(f(at).into(), f(at + 4).into(), f(at + 8).into());
            if !p.is_finite() {
                return Err(format!("accessors[{a}]: position {i} is not finite"));
            }
            out.push(p);
        }
        Ok(out)
    }

    /// The values of unsigned `SCALAR` accessor `a`.
    fn indices(&self, a: usize) -> Result<Vec<u32>, String> {
        let size = match self.gltf.accessors.get(a).map(|acc| acc.component_type) {
            Some(5121) => 1,
            Some(5123) => 2,
            Some(5125) => 4,
            Some(_) => return Err(format!("accessors[{a}]: indices must be unsigned integers")),
            None => return Err(format!("accessor {a} does not exist")),
        };
        let (acc, stride, bytes) = self.view(a, size)?;
        if acc.kind != "SCALAR" {
            return Err(format!("accessors[{a}]: indices must be SCALAR"));
        }
        let mut out = Vec::with_capacity(acc.count as usize);
        for i in 0..acc.count {
            let at = (acc.byte_offset + i * stride) as usize;
            let mut le = [0u8; 4];
            le[..size as usize].copy_from_slice(&bytes[at..at + size as usize]);
            out.push(u32::from_le_bytes(le));
        }
        Ok(out)
    }
}

/// Triangles from indices drawn in `mode` (4 list, 5 strip, 6 fan), checked against `count`.
fn assemble(indices: &[u32], mode: u32, count: usize) -> Result<Vec<[u32; 3]>, String> {
    if let Some(i) = indices.iter().find(|&&i| i as usize >= count) {
        return Err(format!("index {i} out of range ({count} positions)"));
    }
    let n = indices.len();
    Ok(match mode {
        4 if !n.is_multiple_of(3) => return Err(format!("{n} indices is not a multiple of 3")),
        4 => indices
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect(),
        5 => (2..n)
            .map(|i| {
                let (a, b, c) = (indices[i - 2], indices[i - 1], indices[i]);
                if i % 2 == 0 { [a, b, c] } else { [b, a, c] }
            })
            .collect(),
        _ => (2..n)
            .map(|i| [indices[0], indices[i - 1], indices[i]])
            .collect(),
    })
}

/// A node's own transform.
fn local(node: &Node) -> Result<DAffine3, String> {
    if let Some(m) = node.matrix {
        if !m.iter().all(|v| v.is_finite())
            || m[3] != 0.0
            || m[7] != 0.0
            || m[11] != 0.0
            || m[15] != 1.0
        {
            return Err("matrix is not a finite affine transform".into());
        }
        return Ok(DAffine3::from_mat4(DMat4::from_cols_array(&m)));
    }
    let t = DVec3::from_array(node.translation.unwrap_or([0.0; 3]));
    let s = DVec3::from_array(node.scale.unwrap_or([1.0; 3]));
    let r = DQuat::from_array(node.rotation.unwrap_or([0.0, 0.0, 0.0, 1.0]));
    if !(t.is_finite() && s.is_finite() && r.is_finite()) || r.length() == 0.0 {
        return Err("translation, rotation and scale must be finite, the rotation nonzero".into());
    }
    Ok(DAffine3::from_scale_rotation_translation(
        s,
        r.normalize(),
        t,
    ))
}

/// `world` followed by +Y up → +Z up, its 3×3 part snapped to exact 0 and ±1 within 4 ulps.
fn to_z_up(world: DAffine3) -> DAffine3 {
    let snap = |v: f64| {
        let tol = 4.0 * f64::EPSILON;
        [0.0, 1.0, -1.0]
            .into_iter()
            .find(|r| (v - r).abs() <= tol)
            .unwrap_or(v)
    };
    let m = Y_UP_TO_Z_UP * world.matrix3;
    DAffine3::from_mat3_translation(
        DMat3::from_cols_array(&m.to_cols_array().map(snap)),
        Y_UP_TO_Z_UP * world.translation,
    )
}
