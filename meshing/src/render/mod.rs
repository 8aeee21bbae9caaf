//! Pictures of solids and meshes, on the CPU: fields by interval-culled ray casting
//! ([`field`]), meshes by a z-buffer ([`raster`]), both into a depth-and-normal buffer
//! ([`gbuffer`]) that is shaded, given feature edges ([`edges`]) and an axis triad ([`axes`]),
//! alone or as a sheet of four views ([`sheet`]); cross-sections by sign ([`section`]) and mesh
//! defects in colour ([`defects`], and as a coloured PLY: [`defects_ply`]). Orthographic camera
//! ([`camera`]), Lambert shading plus ambient ([`shade`]), PNG output ([`png_out`]).
//!
//! Every pixel is computed from its own inputs only (rayon splits work by tiles or rows, each
//! written by one task), so the bytes do not depend on the thread count. Sizes are checked before
//! any image memory is allocated ([`size`]).

pub mod axes;
pub mod camera;
pub mod defects;
pub mod defects_ply;
mod draw;
pub mod edges;
pub mod field;
mod font;
pub mod gbuffer;
pub mod png_out;
pub mod raster;
pub mod section;
pub mod shade;
pub mod sheet;
pub mod size;

pub use camera::{Camera, View};
pub use gbuffer::GBuffer;
pub use sheet::{Look, picture};
pub use size::{ImageSize, MAX_PIXELS};

use std::path::PathBuf;

/// An RGB image, rows top to bottom.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` pixels, row-major.
    pub pixels: Vec<[u8; 3]>,
}

impl Image {
    /// An image filled with `color` (the size must have been checked by [`ImageSize`]).
    pub fn filled(size: ImageSize, color: [u8; 3]) -> Self {
        Self {
            width: size.width,
            height: size.height,
            pixels: vec![color; size.pixel_count()],
        }
    }

    /// The pixel at column `x`, row `y`.
    pub fn get(&self, x: u32, y: u32) -> [u8; 3] {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// Sets the pixel at `(x, y)` when it lies in the image (signed, so callers may clip).
    pub fn put(&mut self, x: i64, y: i64, color: [u8; 3]) {
        if x >= 0 && y >= 0 && x < i64::from(self.width) && y < i64::from(self.height) {
            self.pixels[y as usize * self.width as usize + x as usize] = color;
        }
    }
}

/// Why a picture could not be made.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// A malformed `WxH`, view or section.
    #[error("{0}")]
    Parse(String),
    /// More pixels than [`MAX_PIXELS`] or a side over [`size::MAX_SIDE`].
    #[error(
        "{width}x{height}: too large (at most {} pixels and {} per side)",
        MAX_PIXELS,
        size::MAX_SIDE
    )]
    TooLarge {
        /// Requested width.
        width: u64,
        /// Requested height.
        height: u64,
    },
    /// Nothing to frame: an empty or unbounded box.
    #[error("{0}")]
    Frame(String),
    /// Writing the file failed.
    #[error(transparent)]
    Io(#[from] crate::io::MeshIoError),
    /// PNG encoding failed.
    #[error("{path}: {message}")]
    Write {
        /// The output file.
        path: PathBuf,
        /// What failed.
        message: String,
    },
}
