//! PNG height maps: an 8- or 16-bit grayscale image (lower bit depths are expanded to 8) decoded
//! with the `png` crate into a [`HeightGrid`] of values in `[0, 1]` (black 0, white 1). Image row 0
//! is the top of the picture and maps to the largest y, so the map seen from above looks like the
//! image.

use super::error::HeightFieldError;
use super::grid::HeightGrid;
use std::path::Path;

/// Decodes a grayscale PNG into heights in `[0, 1]`.
pub fn decode_png(bytes: &[u8]) -> Result<HeightGrid, HeightFieldError> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info()?;
    let size = reader
        .output_buffer_size()
        .ok_or(png::DecodingError::LimitsExceeded)?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf)?;
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

/// Reads and decodes a grayscale PNG file.
pub fn load_png(path: &Path) -> Result<HeightGrid, HeightFieldError> {
    let bytes = std::fs::read(path).map_err(|source| HeightFieldError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    decode_png(&bytes)
}
