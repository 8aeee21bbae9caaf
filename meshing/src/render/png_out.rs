//! PNG encoding (8-bit RGB, fixed settings, so equal images give equal bytes) and atomic writing.
//!
//! Images up to [`SMALL_PIXELS`] are compressed hard (small files for docs and galleries);
//! larger ones with the `png` crate's fast mode (fdeflate), which encodes a 1024 × 1024 picture
//! several times faster than the default at a somewhat larger size.

use super::{Image, RenderError};
use std::path::Path;

/// Images with at most this many pixels are compressed with [`png::Compression::High`].
pub const SMALL_PIXELS: u64 = 512 * 512;

/// The PNG bytes of `image`.
pub fn encode(image: &Image) -> Result<Vec<u8>, png::EncodingError> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, image.width, image.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let pixels = u64::from(image.width) * u64::from(image.height);
    encoder.set_compression(if pixels <= SMALL_PIXELS {
        png::Compression::High
    } else {
        png::Compression::Fast
    });
    let mut writer = encoder.write_header()?;
    writer.write_image_data(image.pixels.as_flattened())?;
    writer.finish()?;
    Ok(bytes)
}

/// Writes `image` to `path` as PNG, atomically (a temporary file renamed over `path`).
pub fn write_png(path: &Path, image: &Image) -> Result<(), RenderError> {
    let failed = |message: String| RenderError::Write {
        path: path.to_path_buf(),
        message,
    };
    let bytes = encode(image).map_err(|e| failed(e.to_string()))?;
    Ok(crate::io::write_atomic(path, |out| out.write_all(&bytes))?)
}

/// Decodes an 8-bit RGB or RGBA PNG (alpha dropped), e.g. to compare a written picture with a
/// new one; `None` for anything else or a malformed file.
pub fn decode(bytes: &[u8]) -> Option<Image> {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().ok()?;
    let info = reader.info();
    let (width, height) = (info.width, info.height);
    if u64::from(width) * u64::from(height) > super::MAX_PIXELS {
        return None;
    }
    let mut buf = vec![0; reader.output_buffer_size()?];
    let frame = reader.next_frame(&mut buf).ok()?;
    if frame.bit_depth != png::BitDepth::Eight {
        return None;
    }
    let channels = match frame.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        _ => return None,
    };
    let pixels = buf[..frame.buffer_size()]
        .chunks_exact(channels)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    Some(Image {
        width,
        height,
        pixels,
    })
}
