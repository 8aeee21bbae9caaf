//! The part of a glTF 2.0 JSON document that mesh input needs: scenes, nodes (hierarchy and
//! transforms), meshes and their primitives, accessors, buffer views and buffers. Everything
//! else (materials, animations, extensions, extras) is skipped; serde_json's nesting limit keeps
//! even skipped values from recursing without bound.

use std::collections::BTreeMap;

use serde::Deserialize;

/// The document.
#[derive(Debug, Default, Deserialize)]
#[serde(default, rename_all = "camelCase")]
pub(super) struct Gltf {
    /// The default scene.
    pub scene: Option<usize>,
    /// Scenes: lists of root nodes.
    pub scenes: Vec<Scene>,
    /// Nodes.
    pub nodes: Vec<Node>,
    /// Meshes.
    pub meshes: Vec<Mesh>,
    /// Accessors.
    pub accessors: Vec<Accessor>,
    /// Buffer views.
    pub buffer_views: Vec<BufferView>,
    /// Buffers.
    pub buffers: Vec<Buffer>,
}

/// A scene.
#[derive(Debug, Default, Deserialize)]
#[serde(default)]
pub(super) struct Scene {
    /// Root nodes.
    pub nodes: Vec<usize>,
}

/// A node: an optional mesh, children, and a matrix or translation, rotation and scale.
#[derive(Debug, Default, Deserialize)]
#[serde(default)]
pub(super) struct Node {
    /// The mesh drawn at this node.
    pub mesh: Option<usize>,
    /// Child nodes.
    pub children: Vec<usize>,
    /// Column-major 4×4 matrix.
    pub matrix: Option<[f64; 16]>,
    /// Translation.
    pub translation: Option<[f64; 3]>,
    /// Unit quaternion `x, y, z, w`.
    pub rotation: Option<[f64; 4]>,
    /// Scale.
    pub scale: Option<[f64; 3]>,
}

/// A mesh.
#[derive(Debug, Default, Deserialize)]
#[serde(default)]
pub(super) struct Mesh {
    /// Its primitives.
    pub primitives: Vec<Primitive>,
}

/// A primitive: attributes, optional indices, drawing mode.
#[derive(Debug, Deserialize)]
pub(super) struct Primitive {
    /// Attribute name → accessor.
    #[serde(default)]
    pub attributes: BTreeMap<String, usize>,
    /// Index accessor.
    #[serde(default)]
    pub indices: Option<usize>,
    /// 0 points, 1 lines, 2 line loop, 3 line strip, 4 triangles, 5 strip, 6 fan.
    #[serde(default = "triangles")]
    pub mode: u32,
}

fn triangles() -> u32 {
    4
}

/// An accessor: typed elements in a buffer view.
#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct Accessor {
    /// The buffer view (absent: all zeros, not supported here).
    #[serde(default)]
    pub buffer_view: Option<usize>,
    /// Offset in the view.
    #[serde(default)]
    pub byte_offset: u64,
    /// 5120..5126.
    pub component_type: u32,
    /// Number of elements.
    pub count: u64,
    /// `SCALAR`, `VEC3`, ...
    #[serde(rename = "type")]
    pub kind: String,
    /// Sparse storage (not supported).
    #[serde(default)]
    pub sparse: Option<serde::de::IgnoredAny>,
}

/// A byte range of a buffer.
#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct BufferView {
    /// The buffer.
    pub buffer: usize,
    /// Start in the buffer.
    #[serde(default)]
    pub byte_offset: u64,
    /// Length.
    pub byte_length: u64,
    /// Distance between elements, when interleaved.
    #[serde(default)]
    pub byte_stride: Option<u64>,
}

/// A buffer: the GLB's BIN chunk when it has no `uri`.
#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub(super) struct Buffer {
    /// Declared length.
    pub byte_length: u64,
    /// External file or data URI (not supported).
    #[serde(default)]
    pub uri: Option<String>,
}
