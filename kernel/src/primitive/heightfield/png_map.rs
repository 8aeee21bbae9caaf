//! PNG height maps: an 8- or 16-bit grayscale image (lower bit depths are expanded to 8) decoded
//! with the `png` crate into a [`HeightGrid`] of values in `[0, 1]` (black 0, white 1). Image row 0
//! is the top of the picture and maps to the largest y, so the map seen from above looks like the
//! image.
//!
//! Budgets: the image's declared size is checked against [`MAX_PNG_SIDE`] and [`MAX_PNG_PIXELS`]
//! before any pixel buffer is allocated (a small file can declare a huge image), and the decoder
//! itself runs under `png::Limits` of [`MAX_PNG_DECODER_BYTES`].

use super::error::HeightFieldError;
use super::grid::HeightGrid;
use crate::files::{DEFAULT_MAX_FILE_BYTES, read_regular_file};
use std::path::Path;

/// The largest width or height of a PNG height map, in pixels.
pub const MAX_PNG_SIDE: u32 = 16_384;
/// The largest pixel count of a PNG height map (4096 × 4096; 128 MiB of `f64` heights).
pub const MAX_PNG_PIXELS: u64 = 1 << 24;
/// What the PNG decoder may allocate (its image buffer included): enough for the largest
/// allowed image at 16 bits per pixel, expanded.
pub const MAX_PNG_DECODER_BYTES: usize = 3 * (1 << 25);

/// Decodes the first frame of a PNG under the budgets, with the decoder's `transformations`.
fn read_frame(
    bytes: &[u8],
    transformations: png::Transformations,
) -> Result<(png::OutputInfo, Vec<u8>), HeightFieldError> {
    let limits = png::Limits {
        bytes: MAX_PNG_DECODER_BYTES,
    };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(bytes), limits);
    decoder.set_transformations(transformations);
    let mut reader = decoder.read_info()?;
    let (width, height) = (reader.info().width, reader.info().height);
    if width > MAX_PNG_SIDE
        || height > MAX_PNG_SIDE
        || u64::from(width) * u64::from(height) > MAX_PNG_PIXELS
    {
        return Err(HeightFieldError::ImageTooLarge { width, height });
    }
    let size = reader
        .output_buffer_size()
        .filter(|&n| n <= MAX_PNG_DECODER_BYTES)
        .ok_or(HeightFieldError::ImageTooLarge { width, height })?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf)?;
    Ok((info, buf))
}

/// Decodes a grayscale PNG into heights in `[0, 1]`.
pub fn decode_png(bytes: &[u8]) -> Result<HeightGrid, HeightFieldError> {
    let (info, buf) = read_frame(bytes, png::Transformations::EXPAND)?;
    let bits = info.bit_depth as u8;
    if info.color_type != png::ColorType::Grayscale || !(bits == 8 || bits == 16) {
        return Err(HeightFieldError::NotGrayscale {
            color: info.color_type,
            bits,
        });
    }
    let (w, h) = (info.width as usize, info.height as usize);
    let mut values = Vec::with_capacity(w * h);
    // Bottom image row first: grid row j = 0 is the smallest y.
    for r in (0..h).rev() {
        let line = &buf[r * info.line_size..(r + 1) * info.line_size];
        if bits == 8 {
            values.extend(line[..w].iter().map(|&b| b as f64 / 255.0));
        } else {
            values.extend(
                line[..2 * w]
                    .chunks_exact(2)
                    .map(|b| u16::from_be_bytes([b[0], b[1]]) as f64 / 65535.0),
            );
        }
    }
    HeightGrid::new(w, h, values)
}

/// Decodes a PNG of any colour type into grey levels in `[0, 1]` as OpenSCAD's `surface()` reads
/// images: 16-bit samples keep their high byte, palettes are expanded, alpha is ignored, and the
/// grey level is the luminance `(0.2126 R + 0.7152 G + 0.0722 B) / 255` (a grey pixel keeps its
/// value). Rows as in [`decode_png`] (the bottom image row first).
pub fn decode_png_luminance(bytes: &[u8]) -> Result<HeightGrid, HeightFieldError> {
    let (info, buf) = read_frame(
        bytes,
        png::Transformations::EXPAND | png::Transformations::STRIP_16,
    )?;
    let channels = match info.color_type {
        png::ColorType::Grayscale => 1,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        png::ColorType::Indexed => {
            return Err(HeightFieldError::NotGrayscale {
                color: info.color_type,
                bits: info.bit_depth as u8,
            });
        }
    };
    let (w, h) = (info.width as usize, info.height as usize);
    let mut values = Vec::with_capacity(w * h);
    for r in (0..h).rev() {
        let line = &buf[r * info.line_size..r * info.line_size + channels * w];
        values.extend(line.chunks_exact(channels).map(|p| {
            let luma = if channels < 3 {
                f64::from(p[0])
            } else {
                0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2])
            };
            luma / 255.0
        }));
    }
    HeightGrid::new(w, h, values)
}

/// Reads and decodes a grayscale PNG file (a regular file of at most
/// [`DEFAULT_MAX_FILE_BYTES`]).
pub fn load_png(path: &Path) -> Result<HeightGrid, HeightFieldError> {
    decode_png(&read_regular_file(path, DEFAULT_MAX_FILE_BYTES)?)
}
